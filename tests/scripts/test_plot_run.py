"""scripts/plot_run.py's choice of what to draw: every load a structure carries, contact
forces included (issue #16: "loop-joint, driver and contact forces included").

A short run of C5 (the bit on bottom: a ground_contact element, the weight on bit) is read
by the script's own load_sources; its contact entry must be the element's normal force as
h5py reads it from the file, and the floating platform's free joint (~1e-8 N of
round-off) must not be among the loads drawn. Run from CTest (tests/CMakeLists.txt:
PlotRun.*), which sets HEAVESIM_BINARY.
"""
import os
import subprocess
import sys
import tempfile
import unittest

import h5py
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BINARY = os.environ.get("HEAVESIM_BINARY", os.path.join(ROOT, "build", "heavesim"))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
sys.path.insert(0, ROOT)
import plot_run  # noqa: E402
import heavesim  # noqa: E402


class LoadsIncludeContacts(unittest.TestCase):
    def test_weight_on_bit_is_a_load_and_the_idle_joint_is_not_drawn(self):
        with tempfile.TemporaryDirectory() as d:
            result = os.path.join(d, "c5.h5")
            run = subprocess.run([BINARY, "run", "cases/c5_bit_on_bottom/h0_passive.yaml", "-o", result, "-q",
                                  "--set", "solver.t_end=30", "--set", "output.evaluate_after=10"], capture_output=True, text=True, cwd=ROOT, timeout=120)
            self.assertEqual(run.returncode, 0, run.stderr)
            r = heavesim.open(result)
            sources = {title: (force, moment) for title, force, moment in plot_run.load_sources(r)}
            self.assertIn("contact bit", sources)
            force, moment = sources["contact bit"]
            self.assertIsNone(moment)
            with h5py.File(result, "r") as f:
                written = int(f.attrs["samples_written"])
                expected = f["forces/bit/force"][:written]
                # Every joint's largest reaction component, read here, not by the script.
                peaks = {name: float(np.max(np.abs(f[f"joints/{name}/reaction_force"][:written])))
                         for name in f["joints"] if "reaction_force" in f[f"joints/{name}"]}
            np.testing.assert_array_equal(np.ravel(force.values), expected)
            self.assertGreater(float(np.mean(expected)), 0.0)  # the bit presses on the formation
            # The drawing rule's input is the file's: the platform's free joint carries
            # round-off (below 1e-6 of the largest load h5py finds), not drawn.
            platform = plot_run.largest(sources["joint platform_motion"][0])
            self.assertEqual(platform, peaks["platform_motion"])
            self.assertLess(platform, 1e-6 * max(max(peaks.values()), float(np.max(np.abs(expected)))))
            os.makedirs(os.path.join(d, "plots"))
            self.assertTrue(plot_run.plot_reactions(r, r["time"], "c5", os.path.join(d, "plots")).endswith(
                "c5_reactions.png"))


if __name__ == "__main__":
    unittest.main()
