"""Tests of `heavesim report` (scripts/report.py) in a real headless browser.

The report of a short drilling run is opened in Debian's Chromium (headless): a
screenshot of the requested size that is not blank, and the DOM after the page's load
event, in which the page's own check has counted the images that did not decode. The
tables are compared with what h5py and numpy read from the result file directly (the
report did not compute those): the hook load's window mean, std, min and max from the raw
series, the Rayleigh MPM from the `statistics` attribute the recorder wrote, one table
row per channel column found by h5py, the efficiency from /summary. A run that failed
(exit 3) gets a banner with its failure time; files that are not heavesim results exit 2.
Run from CTest (tests/CMakeLists.txt: Report.*), which sets HEAVESIM_BINARY.
Chromium is required, not optional: scripts/setup.sh installs it.
"""
import hashlib
import html
import html.parser
import os
import shutil
import struct
import subprocess
import tempfile
import unittest

import h5py
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BINARY = os.environ.get("HEAVESIM_BINARY", os.path.join(ROOT, "build", "heavesim"))
WIDTH, HEIGHT = 1280, 1000  # the screenshot asked for


def heavesim(*arguments):
    return subprocess.run([BINARY] + list(arguments), capture_output=True, text=True, timeout=120, cwd=ROOT)


def chromium(directory, *arguments):
    """Chromium headless with a profile of its own (CTest runs tests in parallel)."""
    executable = shutil.which("chromium")
    if executable is None:
        raise AssertionError("chromium is not installed (Debian package `chromium`; scripts/setup.sh installs it)")
    command = [executable, "--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage", "--hide-scrollbars",
               f"--user-data-dir={directory}/profile"] + list(arguments)
    return subprocess.run(command, capture_output=True, text=True, timeout=90)


class Tables(html.parser.HTMLParser):
    """Every <table id=...>: rows of (text, data-value or None) cells; <body> and
    #incomplete attributes."""

    def __init__(self):
        super().__init__()
        self.tables, self.body, self.incomplete = {}, {}, None
        self._table, self._row, self._cell = None, None, None

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if tag == "body":
            self.body = attrs
        elif tag == "div" and attrs.get("id") == "incomplete":
            self.incomplete = attrs
        elif tag == "table":
            self._table = self.tables.setdefault(attrs.get("id"), [])
        elif tag == "tr" and self._table is not None:
            self._row = []
        elif tag in ("td", "th") and self._row is not None:
            self._cell = ["", attrs.get("data-value")]

    def handle_data(self, data):
        if self._cell is not None:
            self._cell[0] += data

    def handle_endtag(self, tag):
        if tag in ("td", "th") and self._cell is not None:
            self._row.append(tuple(self._cell))
            self._cell = None
        elif tag == "tr" and self._row is not None:
            self._table.append(self._row)
            self._row = None
        elif tag == "table":
            self._table = None


def loaded_dom(directory, page):
    done = chromium(directory, "--dump-dom", f"file://{page}")
    assert done.returncode == 0, done.stderr[-2000:]
    parsed = Tables()
    parsed.feed(done.stdout)
    return parsed


def png_size(path):
    with open(path, "rb") as image:
        header = image.read(24)
    assert header[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    return struct.unpack(">II", header[16:24])


def rows_of(tables, table_id):
    return tables.tables[table_id][1:]  # without the heading row


class DrillingPageInChromium(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.directory = tempfile.TemporaryDirectory()
        d = cls.directory.name
        cls.result = os.path.join(d, "drilling.h5")
        cls.page = os.path.join(d, "drilling_report.html")
        # 60 s of the default rig (wave period 10 s), statistics from t = 20 s: 4 cycles' window.
        run = heavesim("run", "cases/drilling.yaml", "-o", cls.result, "-q", "--set", "solver.t_end=60",
                       "--set", "output.evaluate_after=20")
        assert run.returncode == 0, run.stderr
        cls.made = heavesim("report", cls.result, "-o", cls.page)
        cls.dom = loaded_dom(d, cls.page) if cls.made.returncode == 0 else None

    @classmethod
    def tearDownClass(cls):
        cls.directory.cleanup()

    def setUp(self):
        self.assertEqual(self.made.returncode, 0, self.made.stderr)

    def test_every_image_decoded(self):
        with open(self.page, encoding="utf-8") as page:
            source = page.read()
        images = source.count("<img ")
        self.assertGreaterEqual(images, 5)  # joints, reactions, energy, envelope, spectra, stroke
        self.assertEqual(self.dom.body.get("data-images"), str(images))
        self.assertEqual(self.dom.body.get("data-failed-images"), "0")
        # Self-contained: nothing fetched from elsewhere.
        for outside in ("http://", "https://", 'src="/', "<link"):
            self.assertNotIn(outside, source.replace("data:image/png;base64,", ""))

    def test_a_broken_image_is_counted_and_announced(self):
        # The page's check is a feature: a figure that does not decode shows a banner.
        with open(self.page, encoding="utf-8") as page:
            source = page.read()
        broken = os.path.join(self.directory.name, "broken.html")
        with open(broken, "w", encoding="utf-8") as page:
            page.write(source.replace("data:image/png;base64,iVBOR", "data:image/png;base64,AAAAA", 1))
        dom = loaded_dom(self.directory.name, broken)
        self.assertEqual(dom.body.get("data-failed-images"), "1")

    def test_screenshot_has_its_size_and_is_not_blank(self):
        shot = os.path.join(self.directory.name, "shot.png")
        done = chromium(self.directory.name, f"--screenshot={shot}", f"--window-size={WIDTH},{HEIGHT}",
                        f"file://{self.page}")
        self.assertEqual(done.returncode, 0, done.stderr[-2000:])
        self.assertEqual(png_size(shot), (WIDTH, HEIGHT))
        import matplotlib.image
        pixels = matplotlib.image.imread(shot)[:, :, :3]
        dark = np.mean(pixels.mean(axis=2) < 0.5)  # text and table rules
        self.assertGreater(dark, 0.005)
        self.assertLess(dark, 0.5)
        self.assertGreater(len(np.unique(pixels.reshape(-1, 3), axis=0)), 20)

    def test_statistics_table_has_one_row_per_channel_column(self):
        expected = []
        with h5py.File(self.result) as f:
            extent = f["time"].shape[0]

            def visit(name, node):
                if (isinstance(node, h5py.Dataset) and name != "time" and node.ndim in (1, 2)
                        and node.shape[0] == extent and "units" in node.attrs and node.dtype.kind == "f"):
                    columns = 1 if node.ndim == 1 else node.shape[1]
                    expected.extend(f"/{name}" if node.ndim == 1 else f"/{name}[{c}]" for c in range(columns))

            f.visititems(visit)
        shown = [row[0][0] for row in rows_of(self.dom, "channel-statistics")]
        self.assertEqual(sorted(shown), sorted(expected))
        self.assertGreater(len(shown), 90)

    def test_hook_load_against_the_raw_series(self):
        with h5py.File(self.result) as f:
            n = f.attrs["samples_written"]
            start = f.attrs["statistics_window_start"]
            time = f["time"][:n]
            hook = f["joints/td_string/reaction_force"][:n, 2][time >= start]
            mpm = f["joints/td_string/reaction_force"].attrs["statistics"]["mpm_rayleigh_duration"][2]
        row = next(r for r in rows_of(self.dom, "design-quantities") if r[0][0] == "hook load")
        values = [float(v) for _, v in row[3:8]]
        # Summed in a different order than numpy's pairwise sum: round-off of a 1.6 MN load
        # over 800 samples is ~1e-13 relative; the window std of ~400 N loses 4 digits to the
        # mean's size, so 1e-9 relative on it.
        self.assertAlmostEqual(values[0] / hook.mean(), 1.0, delta=1e-12)
        self.assertAlmostEqual(values[1] / hook.std(ddof=1), 1.0, delta=1e-9)
        self.assertEqual(values[2], hook.min())
        self.assertEqual(values[3], hook.max())
        # The recorder's streaming statistics and `heavesim stats` (the report's) agree to round-off.
        self.assertAlmostEqual(values[4] / mpm, 1.0, delta=1e-12)

    def test_joint_loads_in_both_frames_and_idle_joint_left_out(self):
        rows = rows_of(self.dom, "joint-loads")
        with h5py.File(self.result) as f:
            n = f.attrs["samples_written"]
            window = f["time"][:n] >= f.attrs["statistics_window_start"]
            for frame, suffix in (("joint", "_joint"), ("world", "")):
                series = f[f"joints/td_string/reaction_force{suffix}"][:n, 2][window]
                row = next(r for r in rows if r[0][0] == "td_string" and r[1][0] == frame and r[2][0] == "Fz")
                mean, amplitude = float(row[4][1]), float(row[5][1])
                self.assertAlmostEqual(mean / series.mean(), 1.0, delta=1e-12)
                self.assertAlmostEqual(amplitude, np.max(np.abs(series - series.mean())),
                                       delta=1e-9 * abs(series.mean()))
        joints = {r[0][0] for r in rows}
        self.assertEqual(joints, {"compensator", "crown_tb", "tb_td", "td_string"})  # platform_motion carries nothing
        # Listed: the components over 1e-6 of the largest force in the window, counted here
        # from the raw series (the rig hangs vertically: Fz of each joint, in both frames).
        with h5py.File(self.result) as f:
            n = f.attrs["samples_written"]
            window = f["time"][:n] >= f.attrs["statistics_window_start"]
            series = {(name, frame, kind): f[f"joints/{name}/reaction_{kind}{suffix}"][:n][window]
                      for name in joints for frame, suffix in (("joint", "_joint"), ("world", ""))
                      for kind in ("force", "moment")}
        scale = max(np.abs(v).max() for (_, _, kind), v in series.items() if kind == "force")
        listed = sum(int(np.abs(v[:, c]).max() > 1e-6 * scale) for v in series.values() for c in range(3))
        self.assertEqual(len(rows), listed)
        self.assertEqual(len(rows), 8)

    def test_case_summary_and_compensator(self):
        with h5py.File(self.result) as f:
            sha = f.attrs["case_sha256"]
            yaml_text = f["case/yaml"][()].decode()
            efficiency = f["summary"].attrs["passive_efficiency"]
        self.assertEqual(hashlib.sha256(yaml_text.encode()).hexdigest(), sha)
        summary = {r[0][0]: r[1][0] for r in rows_of(self.dom, "case-summary")}
        self.assertEqual(summary["case SHA-256 (resolved YAML)"], sha)
        self.assertEqual(summary["complete"], "yes")
        self.assertEqual(self.dom.tables["compensators"][0][2][0], "passive")
        compensator = {r[0][0]: r for r in rows_of(self.dom, "compensators")}
        self.assertEqual(float(compensator["efficiency"][2][1]), efficiency)
        self.assertEqual([r[0][0] for r in rows_of(self.dom, "model-joints")],
                         ["platform_motion", "compensator", "crown_tb", "tb_td", "td_string"])
        self.assertIsNone(self.dom.incomplete)


    def test_window_and_duration_asked_for(self):
        # --from and --duration reach every statistic: the hook load's Rayleigh MPM over
        # D = 1 h from t = 30 s against the closed form mean + std sqrt(2 ln(D / Tz)), with
        # Tz = window duration / mean up-crossings counted here (docs/physics/statistics.md §2, §4).
        page = os.path.join(self.directory.name, "window.html")
        made = heavesim("report", self.result, "-o", page, "--from", "30", "--duration", "3600")
        self.assertEqual(made.returncode, 0, made.stderr)
        parsed = Tables()
        with open(page, encoding="utf-8") as text:
            parsed.feed(text.read())
        with h5py.File(self.result) as f:
            n = f.attrs["samples_written"]
            time = f["time"][:n]
            hook = f["joints/td_string/reaction_force"][:n, 2][time >= 30.0 - 1e-9]
            window_time = time[time >= 30.0 - 1e-9]
        mean, std = hook.mean(), hook.std(ddof=1)
        upcrossings = np.count_nonzero((hook[:-1] < mean) & (hook[1:] >= mean))
        tz = (window_time[-1] - window_time[0]) / upcrossings
        expected = mean + std * np.sqrt(2.0 * np.log(3600.0 / tz))
        row = next(r for r in rows_of(parsed, "design-quantities") if r[0][0] == "hook load")
        self.assertAlmostEqual(float(row[3][1]) / mean, 1.0, delta=1e-12)
        # The std's 1e-9 (see above) scaled by sqrt(2 ln N) ~ 5 over a 1.6 MN mean.
        self.assertAlmostEqual(float(row[7][1]), expected, delta=1e-9 * std * 5)
        summary = {r[0][0]: r[1][0] for r in rows_of(parsed, "case-summary")}
        self.assertEqual(summary["evaluation window start [s]"], "30")
        self.assertEqual(summary["MPM duration D [s]"], "3600")


    def test_saved_validation_table_is_counted(self):
        # Three rows in `heavesim validate`'s format, one failing, around its other lines.
        log = os.path.join(self.directory.name, "validate.log")
        with open(log, "w") as out:
            out.write("id   case   quantity   max error  tolerance  result\n"
                      "K1   double pendulum   qdd by ABA, relative   1.01e-14      1e-12  PASS\n"
                      "K1   double pendulum   pin 1 reaction force   1.31e-14      1e-12  PASS\n"
                      "     (0.12 s)\n"
                      "C1   compensator   efficiency T = 8 s   7.00e-03      5e-03  FAIL\n"
                      "1 validation rows FAIL\n")
        page = os.path.join(self.directory.name, "validated.html")
        made = heavesim("report", self.result, "-o", page, "--validation", log)
        self.assertEqual(made.returncode, 0, made.stderr)
        with open(page, encoding="utf-8") as text:
            source = text.read()
        self.assertTrue('id="validation-log" data-rows="3" data-passed="2"' in source, "row counts")
        self.assertTrue("<strong>1 FAIL</strong>" in source, "the FAIL count")


class IrregularSeaPageHasItsRaos(unittest.TestCase):
    """The free MSS semi in a 3-hour JONSWAP sea (cases/hydro/semisub_6dof_irregular_sea.yaml
    with 1000 components, about 2 s): the report carries `heavesim rao OUT.h5`'s table and figure. Each mode's peak
    |RAO| is the largest amplitude with coherence >= 0.9 that h5py reads from the rao.h5 the
    command writes (run here separately), and surge, heave and pitch are within 3 % of
    their peak of the frequency-domain RAO (the bar of docs/rao.md, measured 2.9 %, 1.5 %
    and 2.8 % per bin by Platform6Dof.RaoCommandH1MatchesTheFrequencyDomainRao); the page
    loads in Chromium with every image decoded."""

    def test_rao_table_and_figure(self):
        with tempfile.TemporaryDirectory() as d:
            result, page = os.path.join(d, "sea.h5"), os.path.join(d, "sea_report.html")
            # 1000 components and the window from 200 s, as the RAO command's own test.
            run = heavesim("run", "cases/hydro/semisub_6dof_irregular_sea.yaml", "-o", result, "-q",
                           "--set", "waves.components=1000", "--set", "output.evaluate_after=200")
            self.assertEqual(run.returncode, 0, run.stderr)
            made = heavesim("report", result, "-o", page)
            self.assertEqual(made.returncode, 0, made.stderr)
            separately = heavesim("rao", result, "-o", os.path.join(d, "rao"), "--no-plot", "-q")
            self.assertEqual(separately.returncode, 0, separately.stderr)
            dom = loaded_dom(d, page)
            self.assertEqual(dom.body.get("data-failed-images"), "0")
            rows = {row[0][0]: row for row in rows_of(dom, "rao-table")}
            with h5py.File(os.path.join(d, "rao", "rao.h5"), "r") as f:
                names = [n.decode() if isinstance(n, bytes) else n for n in f["channel_names"][()]]
                # Head seas: sway, roll and yaw are round-off, named but not tabulated.
                self.assertEqual(sorted(rows), ["heave", "pitch", "surge"])
                names = [name for name in names if name in rows]
                for name in names:
                    group = f["channels"][name.lstrip("/").replace("/", ".")]
                    strong = group["coherence"][()] >= 0.9
                    peak = np.max(group["amplitude"][()][strong])
                    self.assertAlmostEqual(float(rows[name][3][1]), peak, delta=1e-12 * peak, msg=name)
            for mode in ("surge", "heave", "pitch"):
                self.assertLess(float(rows[mode][5][1]), 3.0, mode)
                self.assertLess(float(rows[mode][6][1]), 3.0, mode)


class IncompleteRunHasABanner(unittest.TestCase):
    def test_failed_run(self):
        with tempfile.TemporaryDirectory() as d:
            result, page = os.path.join(d, "fault.h5"), os.path.join(d, "fault.html")
            run = heavesim("run", "tests/cases/fault_stiff_strut_rk4.yaml", "-o", result, "-q")
            self.assertEqual(run.returncode, 3, run.stderr)
            made = heavesim("report", result, "-o", page)
            self.assertEqual(made.returncode, 0, made.stderr)
            self.assertIn("INCOMPLETE", made.stdout)
            with h5py.File(result) as f:
                failure_time = f.attrs["failure_time"]
                suggestion = f.attrs["failure_suggestion"]
            dom = loaded_dom(d, page)
            self.assertIsNotNone(dom.incomplete)
            self.assertEqual(float(dom.incomplete["data-failure-time"]), failure_time)
            self.assertEqual(dom.body.get("data-complete"), "0")
            self.assertEqual(dom.body.get("data-failed-images"), "0")
            with open(page, encoding="utf-8") as text:
                shown = html.unescape(text.read())
            self.assertTrue(suggestion in shown, f"the suggestion {suggestion!r} is not in the page")


class BadFiles(unittest.TestCase):
    def assert_refused(self, path, found, *extra):
        with tempfile.TemporaryDirectory() as d:
            page = os.path.join(d, "report.html")
            done = heavesim("report", path, "-o", page, *extra)
            self.assertEqual(done.returncode, 2, done.stderr)
            self.assertIn(found, done.stderr)
            self.assertIn("expected", done.stderr)
            self.assertFalse(os.path.exists(page))

    def test_missing_file(self):
        self.assert_refused("tests/bad_results/no_such_file.h5",
                            "tests/bad_results/no_such_file.h5: found a path that does not exist")

    def test_not_hdf5(self):
        self.assert_refused("tests/bad_results/not_hdf5.h5",
                            "tests/bad_results/not_hdf5.h5: found a file that is not an HDF5 file")

    def test_hdf5_that_is_not_a_result(self):
        self.assert_refused("tests/bad_results/not_a_result.h5", "tests/bad_results/not_a_result.h5: /: found an HDF5 "
                            "file without the root attribute heavesim_version")

    def test_validation_log_missing(self):
        self.assert_refused("tests/bad_results/not_a_result.h5", "tests/bad_results/no_such.log: found no such file",
                            "--validation", "tests/bad_results/no_such.log")

    def test_duration_not_positive(self):
        self.assert_refused("tests/bad_results/not_a_result.h5", "--duration: found -1.0", "--duration", "-1")


if __name__ == "__main__":
    unittest.main()
