"""Tests of the heavesim Python package (docs/python.md). Each compares what the package
returns with something it did not compute: the values h5py reads from the file directly,
the executable's exit codes and messages for the same case, `heavesim stats --json`, and
the file as its run finishes writing it.

Run by CTest (Python.Package) with PYTHONPATH=<build>/python, HEAVESIM_BINARY and
HEAVESIM_SOURCE_DIR set; by hand:
    PYTHONPATH=build/python HEAVESIM_BINARY=build/heavesim /usr/bin/python3 -m unittest discover -s python/tests
"""
import json
import math
import os
import shutil
import subprocess
import tempfile
import time
import unittest

import h5py
import numpy

import heavesim

SOURCE = os.environ.get("HEAVESIM_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
BINARY = os.environ.get("HEAVESIM_BINARY", os.path.join(SOURCE, "build", "heavesim"))
TWO_LINK = os.path.join(SOURCE, "cases/validation/two_link.yaml")
SHORT = {"solver.t_end": 2, "output.interval": 0.01}


def cli(*arguments):
    """The executable: (exit code, stdout, stderr)."""
    done = subprocess.run([BINARY, *arguments], capture_output=True, text=True, timeout=60)
    return done.returncode, done.stdout, done.stderr


class Scratch(unittest.TestCase):
    def setUp(self):
        self.directory = tempfile.mkdtemp(prefix="heavesim_python_")

    def tearDown(self):
        shutil.rmtree(self.directory, ignore_errors=True)

    def path(self, name):
        return os.path.join(self.directory, name)


class ReadingResultFiles(Scratch):
    def test_open_gives_what_h5py_reads_from_the_file(self):
        output = self.path("two_link.h5")
        code, _, errors = cli("run", TWO_LINK, "-o", output, "-q", "--set", "solver.t_end=2", "--set",
                              "output.interval=0.01")
        self.assertEqual(code, 0, errors)
        r = heavesim.open(output)
        with h5py.File(output, "r") as f:
            self.assertTrue(r.complete)
            self.assertEqual(r.samples, f.attrs["samples_written"])
            numpy.testing.assert_array_equal(r.time, f["time"][:])
            expected = set()
            f.visititems(lambda name, node: expected.add("/" + name) if isinstance(node, h5py.Dataset)
                         and name != "time" and node.shape[:1] == f["time"].shape and "units" in node.attrs
                         else None)
            self.assertEqual(set(r.channels), expected)
            for path, channel in r.channels.items():
                numpy.testing.assert_array_equal(channel.values, f[path][:], err_msg=path)
                self.assertEqual(channel.units, f[path].attrs["units"])
                self.assertEqual(channel.description, f[path].attrs["description"])
            numpy.testing.assert_array_equal(r["joints/elbow/reaction_force"], f["joints/elbow/reaction_force"][:])
            numpy.testing.assert_array_equal(r["/joints/elbow/reaction_force"], f["joints/elbow/reaction_force"][:])
            self.assertEqual(r.summary, {k: v.item() if hasattr(v, "item") else v
                                         for k, v in f["summary"].attrs.items() if not k.startswith("_")})
            self.assertEqual(r.attributes["case_name"], f.attrs["case_name"])
            self.assertEqual(r.joints, f["joints"].attrs["order"].split(","))
        with self.assertRaises(KeyError):
            r["joints/no_such_joint/q"]
        r.close()

    def test_statistics_are_those_heavesim_stats_prints(self):
        output = self.path("two_link.h5")
        self.assertEqual(cli("run", TWO_LINK, "-o", output, "-q", "--set", "solver.t_end=2")[0], 0)
        channel = "/joints/elbow/reaction_force"
        code, printed, errors = cli("stats", output, channel, "--json")
        self.assertEqual(code, 0, errors)
        columns = [entry for entry in json.loads(printed)["channels"] if entry["channel"] == channel]
        self.assertEqual(len(columns), 3)
        with heavesim.open(output) as r:
            statistics = r.channels[channel].statistics
            self.assertIn("zero_upcrossing_period", statistics)
            compared = 0
            for entry in columns:
                for name, value in entry["statistics"].items():
                    if name not in statistics or name.startswith("mpm_") or name == "cycles_in_duration":
                        continue  # stats' --duration (3 h) is its own choice; the recorder's is the case's
                    mine = statistics[name][entry["column"]]
                    if value is None:
                        self.assertTrue(math.isnan(mine), name)
                    else:
                        # The same estimators on the same samples, one while recording, one
                        # from the file: equal to the last digits of a sum of ~100 terms.
                        self.assertAlmostEqual(mine, value, delta=1e-12 * max(1.0, abs(value)), msg=name)
                    compared += 1
            self.assertGreater(compared, 30)


class RunningCases(Scratch):
    def test_run_in_process_writes_the_file_the_executable_writes(self):
        output, reference = self.path("in_process.h5"), self.path("cli.h5")
        r = heavesim.run(TWO_LINK, set=SHORT, output=output, csv=self.directory)
        code, _, errors = cli("run", TWO_LINK, "-o", reference, "-q", "--set", "solver.t_end=2", "--set",
                              "output.interval=0.01")
        self.assertEqual(code, 0, errors)
        self.assertTrue(r.complete)
        self.assertEqual(r.samples, 201)
        with h5py.File(reference, "r") as f:
            for path in ("/time", "/joints/shoulder/q", "/joints/elbow/reaction_force", "/signals/total_energy"):
                numpy.testing.assert_array_equal(r[path], f[path][:], err_msg=path)
        # The CSV: one column per recorded value, headed "<dataset><label> [<unit>]".
        with open(self.path("two_link.csv")) as csv:
            header = csv.readline().rstrip("\n").split(",")
        self.assertEqual(header[0], "time [s]")
        self.assertIn(f"joints/elbow/reaction_force.x [{r.channels['/joints/elbow/reaction_force'].units}]", header)

    def test_bad_input_raises_input_error_with_the_executables_message(self):
        bad = os.path.join(SOURCE, "tests/bad_cases/negative_mass.yaml")
        code, _, errors = cli("run", bad, "-o", self.path("bad.h5"), "-q")
        self.assertEqual(code, 2)
        with self.assertRaises(heavesim.InputError) as raised:
            heavesim.run(bad, output=self.path("bad.h5"))
        message = str(raised.exception)
        self.assertIn(f"{bad}:5:", message)
        self.assertIn("bodies[0].mass", message)
        self.assertIn(message, errors)  # "heavesim: bad input: <the same message>"
        self.assertFalse(os.path.exists(self.path("bad.h5")))
        with self.assertRaises(heavesim.InputError) as raised:
            heavesim.check(TWO_LINK, set={"solver.t_end": -1})
        code, _, errors = cli("check", TWO_LINK, "--set", "solver.t_end=-1")
        self.assertEqual(code, 2)
        self.assertIn(str(raised.exception), errors)

    def test_numerical_failure_raises_with_the_partial_result(self):
        fault = os.path.join(SOURCE, "tests/cases/fault_stiff_strut_rk4.yaml")
        output, reference = self.path("fault.h5"), self.path("fault_cli.h5")
        code, _, errors = cli("run", fault, "-o", reference, "-q")
        self.assertEqual(code, 3)
        with self.assertRaises(heavesim.NumericalFailure) as raised:
            heavesim.run(fault, output=output)
        failure = raised.exception
        self.assertEqual(str(failure), errors.strip()[len("heavesim: "):].replace(reference, output))
        self.assertFalse(failure.result.complete)
        with h5py.File(reference, "r") as f:
            self.assertEqual(failure.time, f.attrs["failure_time"])
            self.assertEqual(failure.suggestion, f.attrs["failure_suggestion"])
            numpy.testing.assert_array_equal(failure.result.time, f["time"][: f.attrs["samples_written"]])

    def test_check_prints_what_the_executable_prints(self):
        printed = heavesim.check(TWO_LINK, set={"solver.t_end": 3})
        code, expected, _ = cli("check", TWO_LINK, "--set", "solver.t_end=3")
        self.assertEqual(code, 0)
        self.assertEqual(printed, expected)

    def test_version_is_the_executables(self):
        code, printed, _ = cli("--version")
        self.assertEqual(code, 0)
        self.assertEqual(heavesim.version, printed.strip())


class ReadingWhileTheRunWrites(Scratch):
    def test_a_file_being_written_opens_and_refresh_sees_it_grow(self):
        output = self.path("live.h5")
        # The slow pendulum (rk4 at 1e-6 s): about 2 s of wall time, 24,000 samples
        # flushed 1024 at a time.
        run = subprocess.Popen([BINARY, "run", os.path.join(SOURCE, "tests/cases/long_run.yaml"), "-o", output,
                                "-q", "--set", "solver.t_end=1.2", "--set", "output.interval=5e-5"])
        try:
            deadline = time.monotonic() + 30
            r = None
            while time.monotonic() < deadline:
                if os.path.exists(output):
                    r = r.refresh() if r is not None else heavesim.open(output)
                    if r.samples > 0:
                        break
                time.sleep(0.005)
            self.assertIsNotNone(r)
            self.assertFalse(r.complete)
            first, first_q = r.samples, r["joints/pivot/q"].copy()
            # h5py on its own, with HDF5's default file locking, while the run writes.
            with h5py.File(output, "r") as f:
                self.assertGreaterEqual(f.attrs["samples_written"], first)
                self.assertEqual(f.attrs["complete"], 0)
            while r.samples == first and time.monotonic() < deadline:
                time.sleep(0.005)
                r.refresh()
            second, second_q = r.samples, r["joints/pivot/q"].copy()
            self.assertEqual(run.wait(timeout=60), 0)
        finally:
            run.kill()
            run.wait()
        self.assertGreater(second, first)
        self.assertEqual(len(first_q), first)
        self.assertEqual(len(second_q), second)
        r.refresh()
        self.assertTrue(r.complete)
        with h5py.File(output, "r") as f:  # a plain reader: the writer has closed the file
            q = f["joints/pivot/q"][:]
        self.assertEqual(len(q), 24001)
        numpy.testing.assert_array_equal(first_q, q[:first])
        numpy.testing.assert_array_equal(second_q, q[:second])
        r.close()


if __name__ == "__main__":
    unittest.main()
