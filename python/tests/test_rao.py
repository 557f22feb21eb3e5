"""heavesim.rao (python/heavesim/rao.py, docs/rao.md): the reader against what h5py and the
CSV of the same `heavesim rao` table hold, and the figure it draws. Run with the package's
other tests (Python.Package)."""
import csv
import os
import shutil
import subprocess
import tempfile
import unittest

import h5py
import numpy

from heavesim import rao

SOURCE = os.environ.get("HEAVESIM_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
BINARY = os.environ.get("HEAVESIM_BINARY", os.path.join(SOURCE, "build", "heavesim"))


class RaoTable(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.directory = tempfile.mkdtemp(prefix="heavesim_rao_")
        # The heave-only MSS semi (cases/hydro/regular_wave.yaml) at two periods, 300 s runs.
        done = subprocess.run([BINARY, "rao", os.path.join(SOURCE, "cases/hydro/regular_wave.yaml"), "--periods", "10,12",
                               "--channel", "heave", "--set", "solver.t_end=300", "--set", "output.evaluate_after=150",
                               "--no-plot", "-q", "-o", cls.directory], capture_output=True, text=True, timeout=120)
        assert done.returncode == 0, done.stderr
        cls.table = rao.read(os.path.join(cls.directory, "rao.h5"))

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.directory, ignore_errors=True)

    def test_reader_gives_what_h5py_and_the_csv_hold(self):
        heave = self.table.channels["heave"]
        with h5py.File(os.path.join(self.directory, "rao.h5")) as f:
            numpy.testing.assert_array_equal(heave.amplitude, f["channels/heave/amplitude"][()])
            numpy.testing.assert_array_equal(self.table.period, f["period"][()])
            self.assertEqual(f.attrs["method"], "regular_sweep")
        with open(os.path.join(self.directory, "rao.csv")) as f:
            rows = list(csv.DictReader(f))
        self.assertEqual([float(r["period [s]"]) for r in rows], [10.0, 12.0])
        numpy.testing.assert_allclose([float(r["heave amplitude [m/m]"]) for r in rows], heave.amplitude, rtol=1e-9)
        numpy.testing.assert_allclose([float(r["heave phase [deg]"]) for r in rows], heave.phase, rtol=1e-9)
        self.assertEqual(heave.unit, "m/m")
        self.assertIsNone(heave.coherence)
        self.assertIsNotNone(heave.bem_amplitude)  # the case has BEM data
        # The complex RAO: amplitude and phase put back together, against the CSV's columns.
        numpy.testing.assert_allclose(heave.complex, [float(r["heave amplitude [m/m]"]) *
                                                      numpy.exp(1j * numpy.radians(float(r["heave phase [deg]"])))
                                                      for r in rows], rtol=1e-9)

    def test_figure_writes_a_png(self):
        path = os.path.join(self.directory, "heave.png")
        rao.figure(self.table, path, channels=["heave"])
        with open(path, "rb") as f:
            self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")


if __name__ == "__main__":
    unittest.main()
