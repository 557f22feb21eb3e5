"""Tests of scripts/operability.py (`heavesim operability`) on a hand-made sweep index.

The index is written here with h5py in the layout of docs/sweeps.md: two variants
(active = 0, 1) over a 3 x 2 Hs x Tp diagram. Each cell's values are chosen so that the
expected outcome is known by construction and written out as literals below (which cells
are operable, which criterion limits them); the percentages are recomputed here from the
probabilities, not read from the script. Run from CTest:

    /usr/bin/python3 -m unittest discover -s tests/scripts -p 'test_*.py'
"""
import csv
import json
import os
import subprocess
import sys
import tempfile
import textwrap
import unittest

import h5py
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCRIPT = os.path.join(ROOT, "scripts", "operability.py")
BINARY = os.environ.get("HEAVESIM_BINARY")  # set by CTest: `heavesim operability` runs the script

# Hs x Tp cells, the same for both variants; occurrences as in a scatter table.
HS = [1.0, 3.0, 5.0]
TP = [8.0, 12.0]
OCCURRENCE = {(1.0, 8.0): 200.0, (1.0, 12.0): 100.0, (3.0, 8.0): 300.0, (3.0, 12.0): 250.0, (5.0, 8.0): 100.0, (5.0, 12.0): 50.0}

# Per (active, Hs, Tp): status, efficiency, stroke max [m], end-stop events, hook-load MPM [N] (component 2 of a 2-D column).
RUNS = {
    (0, 1.0, 8.0): ("complete", 0.95, 1.0, 0, 2.0e6),
    (0, 1.0, 12.0): ("complete", 0.93, 1.5, 0, 2.1e6),
    (0, 3.0, 8.0): ("complete", 0.85, 2.0, 0, 2.2e6),      # efficiency violated (first listed)
    (0, 3.0, 12.0): ("complete", 0.80, 2.5, 0, 2.3e6),     # efficiency and stroke violated: efficiency is first
    (0, 5.0, 8.0): ("complete", 0.92, 2.6, 3, 2.6e6),      # stroke, end stops and hook load violated: stroke is first
    # Failed: not operable and its status limits, although the values it left would pass.
    (0, 5.0, 12.0): ("numerical_failure", 0.95, 1.0, 0, 2.0e6),
    (1, 1.0, 8.0): ("complete", 0.99, 0.5, 0, 2.0e6),
    (1, 1.0, 12.0): ("complete", 0.99, 0.6, 0, 2.0e6),
    (1, 3.0, 8.0): ("complete", 0.97, 2.2, 0, 2.1e6),      # operable; stroke margin (2.3-2.2)/2.3 = 0.043 is the least
    (1, 3.0, 12.0): ("complete", 0.96, 1.9, 0, 2.45e6),    # operable; hook load margin (2.5-2.45)/2.5 = 0.02 is the least
    (1, 5.0, 8.0): ("complete", 0.95, 2.0, 0, 2.7e6),      # hook load violated
    (1, 5.0, 12.0): ("complete", 0.95, 2.0, 1, 2.4e6),     # end stop violated
}
# The criteria (CRITERIA below), in this order: efficiency >= 0.9, stroke <= 2.3 m, end-stop
# contacts <= 0.5 (none; margin (0.5 - n)/0.5 = 1 without contact), hook-load MPM <= 2.5 MN.
# Margins as fractions of the limit, worked by hand for the cells where the least one decides.
EXPECTED = {  # (active, Hs, Tp): (operable, limiting criterion)
    (0, 1.0, 8.0): (True, "efficiency"),        # margins 0.056, 0.565, 1, 0.2
    (0, 1.0, 12.0): (True, "efficiency"),       # 0.033, 0.348, 1, 0.16
    (0, 3.0, 8.0): (False, "efficiency"),
    (0, 3.0, 12.0): (False, "efficiency"),      # efficiency and stroke violated: the first listed
    (0, 5.0, 8.0): (False, "stroke"),           # stroke -0.13, end stops -5 (the worst), hook -0.04: the first listed
    (0, 5.0, 12.0): (False, "numerical_failure"),
    (1, 1.0, 8.0): (True, "efficiency"),        # 0.1, 0.78, 1, 0.2
    (1, 1.0, 12.0): (True, "efficiency"),       # 0.1, 0.74, 1, 0.2
    (1, 3.0, 8.0): (True, "stroke"),            # 0.078, 0.043, 1, 0.16
    (1, 3.0, 12.0): (True, "hook load MPM"),    # 0.067, 0.174, 1, 0.02
    (1, 5.0, 8.0): (False, "hook load MPM"),
    (1, 5.0, 12.0): (False, "end stop contact"),
}
CRITERIA = """\
criteria:
  - {name: efficiency, column: summary/passive_efficiency, at_least: 0.9}
  - {name: stroke, column: summary/passive_stroke_max_m, at_most: 2.3}
  - name: end stop contact
    column: summary/passive_end_stop_events_upper
    at_most: 0.5
  - name: hook load MPM
    column: statistics/joints.td_string.reaction_force/mpm_rayleigh_duration
    component: 2
    at_most: 2.5e6
"""


def write_index(path, runs=RUNS, variant_by_base_case=False):
    keys = sorted(runs)
    count = len(keys)
    with h5py.File(path, "w") as f:
        f.attrs["run_count"] = count
        f.attrs["complete"] = 1
        if variant_by_base_case:  # the variants are two base cases (docs/sweeps.md: `base` as a list)
            cases = ["../c4_irregular_waves/h0_passive.yaml", "../c4_irregular_waves/h0_active.yaml"]
            f.create_dataset("runs/base_case", data=[cases[k[0]] for k in keys], dtype=h5py.string_dtype())
        else:
            f.create_dataset("variables/parameters.active", data=np.array([k[0] for k in keys], dtype=float)).attrs["path"] = "parameters.active"
        f.create_dataset("variables/Hs", data=np.array([k[1] for k in keys]))
        f.create_dataset("variables/Tp", data=np.array([k[2] for k in keys]))
        # Normalised per variant: each variant's sea states sum to 1.
        total = sum(OCCURRENCE.values())
        f.create_dataset("scatter/probability", data=np.array([OCCURRENCE[k[1:]] / total for k in keys]))
        text = h5py.string_dtype()
        f.create_dataset("runs/status", data=[runs[k][0] for k in keys], dtype=text)
        f.create_dataset("runs/exit_code", data=np.array([0 if runs[k][0] == "complete" else 3 for k in keys]))
        f.create_dataset("runs/message", data=["" if runs[k][0] == "complete" else "t = 412 s: IDA failed" for k in keys], dtype=text)
        f.create_dataset("summary/passive_efficiency", data=np.array([runs[k][1] for k in keys]))
        f.create_dataset("summary/passive_stroke_max_m", data=np.array([runs[k][2] for k in keys]))
        f.create_dataset("summary/passive_end_stop_events_upper", data=np.array([runs[k][3] for k in keys]))
        hook = np.zeros((count, 3))
        hook[:, 2] = [runs[k][4] for k in keys]
        hook[:, 0] = 9e9  # the other components would violate: the criterion must read component 2
        f.create_dataset("statistics/joints.td_string.reaction_force/mpm_rayleigh_duration", data=hook)
    return keys


def run_tool(*arguments):
    command = [BINARY, "operability"] if BINARY else [sys.executable, SCRIPT]
    return subprocess.run(command + list(arguments), capture_output=True, text=True, timeout=60)


class OperabilityOnAHandMadeIndex(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.directory = tempfile.TemporaryDirectory()
        cls.index = os.path.join(cls.directory.name, "index.h5")
        cls.keys = write_index(cls.index)
        cls.criteria = os.path.join(cls.directory.name, "criteria.yaml")
        with open(cls.criteria, "w") as f:
            f.write(CRITERIA)
        cls.output = os.path.join(cls.directory.name, "out")
        cls.result = run_tool(cls.index, "--criteria", cls.criteria, "-o", cls.output, "--json")

    def test_succeeds(self):
        self.assertEqual(self.result.returncode, 0, self.result.stderr)

    def test_operable_and_limiting_criterion_per_cell(self):
        summary = json.loads(self.result.stdout)
        cells = {}
        for variant in summary["variants"]:
            active = int(variant["variables"]["parameters.active"])
            for cell in variant["cells"]:
                cells[(active, cell["Hs"], cell["Tp"])] = (cell["operable"], cell["limiting"])
        self.assertEqual(cells, EXPECTED)

    def test_percentages_weighted_by_occurrence(self):
        summary = json.loads(self.result.stdout)
        total = sum(OCCURRENCE.values())
        for variant in summary["variants"]:
            active = int(variant["variables"]["parameters.active"])
            operable = sum(OCCURRENCE[(hs, tp)] for (a, hs, tp), (ok, _) in EXPECTED.items() if a == active and ok)
            # Round-off: sums of six probabilities of order 0.1, so 1e-12 of 100 %.
            self.assertAlmostEqual(variant["operability_percent"], 100.0 * operable / total, delta=1e-12)
        # The figures themselves, by hand: passive 300/1000 = 30 %, active 850/1000 = 85 %.
        by_active = {int(v["variables"]["parameters.active"]): v["operability_percent"] for v in summary["variants"]}
        self.assertAlmostEqual(by_active[0], 30.0, delta=1e-12)
        self.assertAlmostEqual(by_active[1], 85.0, delta=1e-12)

    def test_failed_run_is_counted_not_operable_with_its_status(self):
        summary = json.loads(self.result.stdout)
        passive = next(v for v in summary["variants"] if v["variables"]["parameters.active"] == 0)
        self.assertEqual(passive["failed_runs"], 1)
        failed = next(c for c in passive["cells"] if c["status"] != "complete")
        self.assertEqual((failed["Hs"], failed["Tp"], failed["operable"], failed["limiting"]), (5.0, 12.0, False, "numerical_failure"))

    def test_margins_are_fractions_of_the_limit(self):
        summary = json.loads(self.result.stdout)
        active = next(v for v in summary["variants"] if v["variables"]["parameters.active"] == 1)
        cell = next(c for c in active["cells"] if (c["Hs"], c["Tp"]) == (3.0, 12.0))
        self.assertAlmostEqual(cell["margins"]["hook load MPM"], (2.5e6 - 2.45e6) / 2.5e6, delta=1e-15)
        self.assertAlmostEqual(cell["margins"]["efficiency"], (0.96 - 0.9) / 0.9, delta=1e-15)
        self.assertAlmostEqual(cell["margins"]["stroke"], (2.3 - 1.9) / 2.3, delta=1e-15)
        self.assertEqual(cell["margins"]["end stop contact"], 1.0)

    def test_csv_has_a_row_per_run(self):
        with open(os.path.join(self.output, "operability.csv")) as f:
            rows = list(csv.DictReader(f))
        self.assertEqual(len(rows), len(RUNS))
        yes = {(float(r["Hs_m"]), float(r["Tp_s"]), r["variant"]) for r in rows if r["operable"] == "yes"}
        self.assertEqual(len(yes), sum(1 for ok, _ in EXPECTED.values() if ok))

    def test_plot_is_a_png(self):
        path = os.path.join(self.output, "operability.png")
        with open(path, "rb") as f:
            header = f.read(8)
        self.assertEqual(header, b"\x89PNG\r\n\x1a\n")
        self.assertGreater(os.path.getsize(path), 10000)  # a figure, not an empty canvas


class VariantsByBaseCase(unittest.TestCase):
    """A sweep over a list of base cases: each case is a variant, named by its file."""

    def test_each_base_case_is_a_variant(self):
        with tempfile.TemporaryDirectory() as directory:
            index = os.path.join(directory, "index.h5")
            write_index(index, variant_by_base_case=True)
            criteria = os.path.join(directory, "criteria.yaml")
            with open(criteria, "w") as f:
                f.write(CRITERIA)
            result = run_tool(index, "--criteria", criteria, "--json")
            self.assertEqual(result.returncode, 0, result.stderr)
            by_case = {v["variables"]["case"]: v["operability_percent"] for v in json.loads(result.stdout)["variants"]}
            self.assertEqual(set(by_case), {"h0_passive", "h0_active"})
            self.assertAlmostEqual(by_case["h0_passive"], 30.0, delta=1e-12)
            self.assertAlmostEqual(by_case["h0_active"], 85.0, delta=1e-12)


class BadCriteriaFiles(unittest.TestCase):
    """Each bad criteria file: exit 2, `file:line:column: key path: found ...; expected ...`."""

    @classmethod
    def setUpClass(cls):
        cls.directory = tempfile.TemporaryDirectory()
        cls.index = os.path.join(cls.directory.name, "index.h5")
        write_index(cls.index)

    def refused(self, text, line, key_path, words):
        path = os.path.join(self.directory.name, "bad.yaml")
        with open(path, "w") as f:
            f.write(textwrap.dedent(text))
        result = run_tool(self.index, "--criteria", path, "-o", os.path.join(self.directory.name, "out"))
        self.assertEqual(result.returncode, 2, result.stderr)
        self.assertIn(f"{path}:{line}:", result.stderr)
        if key_path:
            self.assertIn(f": {key_path}: found ", result.stderr)
        self.assertIn("; expected ", result.stderr)
        self.assertIn(words, result.stderr)
        self.assertNotIn("Traceback", result.stderr)

    def test_unknown_column_with_did_you_mean(self):
        self.refused("""\
            criteria:
              - {name: efficiency, column: summary/passive_eficiency, at_least: 0.9}
            """, 2, "criteria[0].column", "did you mean 'summary/passive_efficiency'")

    def test_unknown_key(self):
        self.refused("""\
            criteria:
              - name: stroke
                column: summary/passive_stroke_max_m
                at_mots: 2.3
            """, 4, "criteria[0].at_mots", "did you mean 'at_most'")

    def test_no_limit(self):
        self.refused("""\
            criteria:
              - {name: stroke, column: summary/passive_stroke_max_m}
            """, 2, "criteria[0].at_most", "neither at_least nor at_most")

    def test_limit_not_a_number(self):
        self.refused("""\
            criteria:
              - name: stroke
                column: summary/passive_stroke_max_m
                at_most: two metres
            """, 4, "criteria[0].at_most", "'two metres'")

    def test_limit_not_finite(self):
        self.refused("""\
            criteria:
              - {name: stroke, column: summary/passive_stroke_max_m, at_most: .nan}
            """, 2, "criteria[0].at_most", "a finite number")

    def test_duplicate_name(self):
        self.refused("""\
            criteria:
              - {name: stroke, column: summary/passive_stroke_max_m, at_most: 2.3}
              - {name: stroke, column: summary/passive_efficiency, at_least: 0.9}
            """, 3, "criteria[1].name", "'stroke' again")

    def test_duplicate_key(self):
        self.refused("""\
            criteria:
              - name: stroke
                column: summary/passive_stroke_max_m
                at_most: 2.3
                at_most: 2.0
            """, 5, "criteria[0].at_most", "the first at line 4")

    def test_reversed_band(self):
        self.refused("""\
            criteria:
              - {name: stroke, column: summary/passive_stroke_max_m, at_least: 3, at_most: 2.3}
            """, 2, "criteria[0].at_least", "at_least <= at_most")

    def test_two_dimensional_column_without_component(self):
        self.refused("""\
            criteria:
              - name: hook load
                column: statistics/joints.td_string.reaction_force/mpm_rayleigh_duration
                at_most: 2.5e6
            """, 3, "criteria[0].column", "a component for a 2-D column")

    def test_component_out_of_range(self):
        self.refused("""\
            criteria:
              - name: hook load
                column: statistics/joints.td_string.reaction_force/mpm_rayleigh_duration
                component: 3
                at_most: 2.5e6
            """, 3, "criteria[0].column", "component 3")

    def test_no_criteria_list(self):
        self.refused("""\
            criteria: {name: stroke}
            """, 1, "criteria", "a list of criteria")

    def test_unknown_top_level_key(self):
        self.refused("""\
            criterion:
              - {name: stroke, column: summary/passive_stroke_max_m, at_most: 2.3}
            """, 1, "criterion", "did you mean 'criteria'")

    def test_invalid_yaml_at_its_line(self):
        self.refused("""\
            criteria:
              - {name: stroke, column: summary/passive_stroke_max_m, at_most: 2.3
              - {name: efficiency}
            """, 3, "", "invalid YAML")

    def test_missing_index_is_bad_input_naming_it(self):
        result = run_tool(os.path.join(self.directory.name, "missing.h5"), "--criteria", "whatever.yaml")
        self.assertEqual(result.returncode, 2)
        self.assertIn("missing.h5: found no readable file", result.stderr)


if __name__ == "__main__":
    unittest.main()
