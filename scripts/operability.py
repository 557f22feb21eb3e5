#!/usr/bin/python3
"""Operability of a sweep over a scatter diagram: `heavesim operability` runs this script.

    heavesim operability INDEX.h5 --criteria CRITERIA.yaml [-o DIR] [--json]
    /usr/bin/python3 scripts/operability.py INDEX.h5 --criteria CRITERIA.yaml [-o DIR] [--json]

Reads the index a sweep wrote (docs/sweeps.md: /variables, /scatter/probability, /runs,
/summary, /statistics) and a criteria file (docs/operability.md):

    criteria:
      - {name: efficiency, column: summary/passive_efficiency, at_least: 0.9}
      - {name: stroke, column: summary/passive_stroke_max_m, at_most: 2.3}

For every run: each criterion's margin (limit - value for at_most, value - limit for
at_least, divided by `scale`, by default |limit|, or 1 for a limit of 0), operable when no
margin is negative and the run completed; the limiting criterion is the first violated
one in the file's order, else the one with the least margin; a run that did not complete
is not operable and its status is the limiting criterion. Per design variant (each
combination of the variables other than Hs and Tp, and the base case when the sweep has
several): the operability, the occurrence
probability of the operable sea states over that of all of the variant's sea states.

Writes DIR/operability.csv (one row per run), DIR/operability.json (the summary and every
run) and DIR/operability.png (the scatter diagram, one panel per variant, each cell
coloured by its limiting criterion); DIR defaults to the index's directory. Prints the
percentages, or with --json the JSON summary.

Exit codes follow heavesim's contract (docs/reliability.md): 0 done, 2 bad input (an
unreadable index or a bad criteria file: `file:line:column: key: found ...; expected ...`),
1 anything else (an output that cannot be written).

Debian's /usr/bin/python3 with python3-numpy, python3-h5py, python3-matplotlib and
python3-yaml.
"""
import argparse
import csv
import difflib
import json
import math
import os
import stat
import sys

import h5py
import numpy as np
import yaml

MAX_CRITERIA_FILE_BYTES = 16 * 1024 * 1024  # the case files' bound (docs/reliability.md)
CRITERION_KEYS = ("name", "column", "at_least", "at_most", "scale", "component")
TOP_LEVEL_KEYS = ("criteria",)
SEA_STATE_VARIABLES = ("Hs", "Tp")


class InputError(Exception):
    """Bad input, exit 2: the same text as heavesim's InputError (app/case/input_error.cpp)."""

    def __init__(self, file, line, column, key_path, found, expected):
        location = f"{file}:{line}:{column}" if line > 0 else file
        key = f"{key_path}: " if key_path else ""
        super().__init__(f"{location}: {key}found {found}; expected {expected}")


def did_you_mean(word, choices):
    close = difflib.get_close_matches(word, list(choices), n=1, cutoff=0.6)
    return f" (did you mean '{close[0]}'?)" if close else ""


# ---------------------------------------------------------------- the criteria file

class Criterion:
    def __init__(self, name, column, at_least, at_most, scale, component, node):
        self.name, self.column, self.at_least, self.at_most = name, column, at_least, at_most
        self.scale, self.component, self.node = scale, component, node

    def margin(self, value):
        """Margin in units of `scale` (negative: violated); NaN when the value is not finite."""
        if not math.isfinite(value):
            return math.nan
        margins = []
        if self.at_most is not None:
            margins.append((self.at_most - value) / self.scale)
        if self.at_least is not None:
            margins.append((value - self.at_least) / self.scale)
        return min(margins)

    def limits(self):
        limits = []
        if self.at_least is not None:
            limits.append(f"≥ {self.at_least:g}")
        if self.at_most is not None:
            limits.append(f"≤ {self.at_most:g}")
        return ", ".join(limits)


def mark(node):
    return node.start_mark.line + 1, node.start_mark.column + 1


def scalar_text(node):
    return node.value if isinstance(node, yaml.ScalarNode) else ("a list" if isinstance(node, yaml.SequenceNode) else "a mapping")


def read_mapping(path, node, key_path, allowed):
    """{key: (key node, value node)} of a mapping node; duplicate and unknown keys are bad input."""
    if not isinstance(node, yaml.MappingNode):
        raise InputError(path, *mark(node), key_path, scalar_text(node), "a mapping")
    entries = {}
    for key_node, value_node in node.value:
        key = key_node.value if isinstance(key_node, yaml.ScalarNode) else None
        where = f"{key_path}.{key}" if key_path else str(key)
        if key is None:
            raise InputError(path, *mark(key_node), key_path, scalar_text(key_node), "a key name")
        if key in entries:
            first_line = entries[key][0].start_mark.line + 1
            raise InputError(path, *mark(key_node), where, f"a second '{key}' (the first at line {first_line})", "each key once")
        if key not in allowed:
            raise InputError(path, *mark(key_node), where, f"the unknown key '{key}'{did_you_mean(key, allowed)}",
                             "one of " + ", ".join(allowed))
        entries[key] = (key_node, value_node)
    return entries


def read_number(path, node, key_path):
    """A finite number. PyYAML's YAML 1.1 resolver reads 2.5e6 as text, so plain scalars are parsed here."""
    if isinstance(node, yaml.ScalarNode) and node.style is None:
        try:
            value = float(node.value.replace("_", ""))
            if math.isfinite(value) and abs(value) <= 1e15:  # heavesim's bound on any number
                return value
        except ValueError:
            pass
    raise InputError(path, *mark(node), key_path, f"'{scalar_text(node)}'", "a finite number, |x| <= 1e15")


def read_text(path, node, key_path):
    if isinstance(node, yaml.ScalarNode) and node.tag == "tag:yaml.org,2002:str" and node.value.strip():
        return node.value.strip()
    found = "nothing" if isinstance(node, yaml.ScalarNode) and not node.value.strip() else f"'{scalar_text(node)}'"
    raise InputError(path, *mark(node), key_path, found, "a non-empty text")


def check_regular_file(path, kind, limit):
    try:
        info = os.stat(path)
    except OSError as error:
        raise InputError(path, 0, 0, "", f"no readable file ({error.strerror})", kind) from None
    if not stat.S_ISREG(info.st_mode):
        raise InputError(path, 0, 0, "", "something that is not a regular file", kind)
    if info.st_size > limit:
        raise InputError(path, 0, 0, "", f"{info.st_size} bytes", f"{kind} of at most {limit} bytes")


def load_criteria(path, index):
    """The criteria of `path`, each checked against the index's columns."""
    check_regular_file(path, "a criteria file (YAML)", MAX_CRITERIA_FILE_BYTES)
    try:
        with open(path, encoding="utf-8") as f:
            root = yaml.compose(f, Loader=yaml.SafeLoader)
    except yaml.MarkedYAMLError as error:
        where = error.problem_mark or error.context_mark
        line, column = (where.line + 1, where.column + 1) if where else (0, 0)
        raise InputError(path, line, column, "", f"invalid YAML ({error.problem or error.context})", "a YAML mapping") from None
    except (yaml.YAMLError, UnicodeDecodeError) as error:
        raise InputError(path, 0, 0, "", f"invalid YAML ({error})", "a YAML mapping") from None
    if root is None:
        raise InputError(path, 0, 0, "", "an empty file", "a mapping with 'criteria'")
    top = read_mapping(path, root, "", TOP_LEVEL_KEYS)
    if "criteria" not in top:
        raise InputError(path, *mark(root), "criteria", "no 'criteria'", "a list of criteria")
    items = top["criteria"][1]
    if not isinstance(items, yaml.SequenceNode) or not items.value:
        raise InputError(path, *mark(items), "criteria", scalar_text(items) if not isinstance(items, yaml.SequenceNode) else "an empty list",
                         "a list of criteria, each {name, column, at_least and/or at_most}")
    criteria, names = [], {}
    for number, item in enumerate(items.value):
        key_path = f"criteria[{number}]"
        entries = read_mapping(path, item, key_path, CRITERION_KEYS)
        for required in ("name", "column"):
            if required not in entries:
                raise InputError(path, *mark(item), f"{key_path}.{required}", f"no '{required}'",
                                 "name (text) and column (an index dataset, e.g. summary/passive_efficiency)")
        name = read_text(path, entries["name"][1], f"{key_path}.name")
        if name in names:
            raise InputError(path, *mark(entries["name"][1]), f"{key_path}.name",
                             f"'{name}' again (criteria[{names[name]}] has it)", "a name used once")
        names[name] = number
        limits = {key: read_number(path, entries[key][1], f"{key_path}.{key}") for key in ("at_least", "at_most") if key in entries}
        if not limits:
            raise InputError(path, *mark(item), f"{key_path}.at_most", "neither at_least nor at_most", "at least one limit")
        if len(limits) == 2 and limits["at_least"] > limits["at_most"]:
            raise InputError(path, *mark(entries["at_least"][1]), f"{key_path}.at_least",
                             f"{limits['at_least']:g} above at_most = {limits['at_most']:g}", "at_least <= at_most")
        if "scale" in entries:
            scale = read_number(path, entries["scale"][1], f"{key_path}.scale")
            if not scale > 0:
                raise InputError(path, *mark(entries["scale"][1]), f"{key_path}.scale", f"{scale:g}", "a scale > 0 (the margin's unit)")
        else:  # the margin as a fraction of the limit; a limit of 0 in the column's units
            scale = max(abs(value) for value in limits.values()) or 1.0
        component = None
        if "component" in entries:
            value = read_number(path, entries["component"][1], f"{key_path}.component")
            if value != int(value) or value < 0:
                raise InputError(path, *mark(entries["component"][1]), f"{key_path}.component", f"{value:g}", "a column number >= 0")
            component = int(value)
        column_node = entries["column"][1]
        column = read_text(path, column_node, f"{key_path}.column").strip("/")
        index.check_column(path, column_node, f"{key_path}.column", column, component)
        criteria.append(Criterion(name, column, limits.get("at_least"), limits.get("at_most"), scale, component, item))
    return criteria


# ---------------------------------------------------------------- the sweep's index

def text_values(dataset):
    return [value.decode() if isinstance(value, bytes) else str(value) for value in dataset[()]]


class Index:
    """The sweep's index file (layout: docs/sweeps.md), read once."""

    def __init__(self, path):
        self.path = path
        check_regular_file(path, "a sweep index (HDF5)", 1 << 40)
        try:
            self.file = h5py.File(path, "r")
        except OSError as error:
            raise InputError(path, 0, 0, "", f"a file HDF5 cannot open ({error})", "a sweep index (HDF5)") from None
        self.status = self.texts("runs/status")
        self.count = len(self.status)
        self.message = self.texts("runs/message") if "runs/message" in self.file else [""] * self.count
        self.probability = self.numbers("scatter/probability")
        self.sea_state = {name: self.numbers(f"variables/{name}") for name in SEA_STATE_VARIABLES}
        self.design = {}  # the other variables: what makes a variant
        for name, dataset in self.file["variables"].items():
            if name not in SEA_STATE_VARIABLES and isinstance(dataset, h5py.Dataset):
                values = text_values(dataset) if dataset.dtype.kind in "SOU" else list(self.numbers(f"variables/{name}"))
                self.design[name] = values
        if "runs/base_case" in self.file:  # a sweep over a list of base cases: each case is a design
            cases = self.texts("runs/base_case")
            if len(set(cases)) > 1:
                self.design["case"] = [os.path.splitext(os.path.basename(case))[0] for case in cases]
        self.columns = []
        self.file.visititems(lambda name, item: self.columns.append(name)
                             if isinstance(item, h5py.Dataset) and name.split("/")[0] in ("summary", "statistics") else None)

    def dataset(self, name):
        if name not in self.file or not isinstance(self.file[name], h5py.Dataset):
            raise InputError(self.path, 0, 0, f"/{name}", "no such dataset", "a sweep index with /runs, /variables/Hs, /variables/Tp and /scatter/probability")
        return self.file[name]

    def texts(self, name):
        return text_values(self.dataset(name))

    def numbers(self, name):
        dataset = self.dataset(name)
        if dataset.dtype.kind not in "fiu" or dataset.ndim != 1 or (hasattr(self, "count") and dataset.shape[0] != self.count):
            expected = f"float64[{self.count}]" if hasattr(self, "count") else "float64[runs]"
            raise InputError(self.path, 0, 0, f"/{name}", f"{dataset.dtype}{list(dataset.shape)}", expected + ", one value per run")
        return np.asarray(dataset[()], dtype=float)

    def check_column(self, criteria_path, node, key_path, column, component):
        if column not in self.file or not isinstance(self.file[column], h5py.Dataset):
            choices = sorted(self.columns)
            hint = did_you_mean(column, choices)
            listed = ", ".join(choices[:8]) + (", ..." if len(choices) > 8 else "")
            raise InputError(criteria_path, *mark(node), key_path, f"'{column}', not a dataset of {self.path}{hint}",
                             f"an index column under summary/ or statistics/ ({listed})")
        dataset = self.file[column]
        if component is None and dataset.ndim == 2 and dataset.shape[1] == 1:
            component = 0  # a one-column channel needs no component
        rows_ok = dataset.dtype.kind in "fiu" and dataset.shape[:1] == (self.count,)
        if not rows_ok or dataset.ndim > 2 or (dataset.ndim == 2 and component is None):
            raise InputError(criteria_path, *mark(node), key_path, f"'{column}' of type {dataset.dtype}{list(dataset.shape)}",
                             f"numbers, one per run ({self.count}); a component for a 2-D column")
        if component is not None and (dataset.ndim != 2 or component >= dataset.shape[1]):
            columns = dataset.shape[1] if dataset.ndim == 2 else 1
            raise InputError(criteria_path, *mark(node), key_path, f"component {component} of '{column}' with {columns} column(s)",
                             "a component of a 2-D column, below its column count")

    def values(self, criterion):
        data = np.asarray(self.file[criterion.column][()], dtype=float)
        if data.ndim == 2:
            return data[:, criterion.component or 0]
        return data


# ---------------------------------------------------------------- evaluation

def evaluate(index, criteria):
    """Per run: margins [criterion], operable, limiting criterion (name)."""
    values = np.array([index.values(criterion) for criterion in criteria])  # [criterion, run]
    runs = []
    for run in range(index.count):
        margins = [criterion.margin(values[k, run]) for k, criterion in enumerate(criteria)]
        complete = index.status[run] == "complete"
        violated = [k for k, margin in enumerate(margins) if not margin >= 0.0]  # NaN: no value, violated
        if not complete:
            limiting = index.status[run]
        elif violated:
            limiting = criteria[violated[0]].name
        else:
            limiting = criteria[int(np.argmin(margins))].name
        runs.append({"run": run, "Hs": index.sea_state["Hs"][run], "Tp": index.sea_state["Tp"][run],
                     "probability": index.probability[run], "status": index.status[run],
                     "message": index.message[run], "operable": complete and not violated,
                     "limiting": limiting, "values": list(values[:, run]), "margins": margins})
    return runs


def variants_of(index):
    """[(label, {variable: value}, [run numbers])] in the order the variants first appear."""
    names = sorted(index.design)
    groups = {}
    for run in range(index.count):
        key = tuple(index.design[name][run] for name in names)
        groups.setdefault(key, []).append(run)
    variants = []
    for key, runs in groups.items():
        assignment = dict(zip(names, key))
        label = ", ".join(f"{name} = {value:g}" if isinstance(value, float) else f"{name} = {value}"
                          for name, value in assignment.items()) or "all runs"
        variants.append((label, assignment, runs))
    return variants


def operability_percent(runs, members):
    """100 x (probability of the operable sea states) / (probability of all of them)."""
    total = sum(runs[run]["probability"] for run in members)
    operable = sum(runs[run]["probability"] for run in members if runs[run]["operable"])
    return (100.0 * operable / total if total > 0 else math.nan), total


# ---------------------------------------------------------------- outputs

def json_number(value):
    return value if isinstance(value, (int, str, bool)) or (value is not None and math.isfinite(value)) else None


def write_csv(path, criteria, runs, variant_of_run):
    with open(path, "w", newline="") as f:
        writer = csv.writer(f)
        header = ["run", "variant", "Hs_m", "Tp_s", "probability", "status", "operable", "limiting"]
        for criterion in criteria:
            header += [f"{criterion.name} value", f"{criterion.name} margin"]
        writer.writerow(header)
        for run in runs:
            row = [run["run"], variant_of_run[run["run"]], f"{run['Hs']:g}", f"{run['Tp']:g}", f"{run['probability']:.9g}",
                   run["status"], "yes" if run["operable"] else "no", run["limiting"]]
            for value, margin in zip(run["values"], run["margins"]):
                row += [f"{value:.9g}", f"{margin:.6g}"]
            writer.writerow(row)


def summary_of(index, criteria, runs, variants):
    result = {"index": index.path,
              "criteria": [{"name": c.name, "column": c.column, "at_least": c.at_least, "at_most": c.at_most,
                            "scale": c.scale, "component": c.component} for c in criteria],
              "variants": []}
    for label, assignment, members in variants:
        percent, total = operability_percent(runs, members)
        limiting = {}
        for run in members:
            if not runs[run]["operable"]:
                limiting[runs[run]["limiting"]] = limiting.get(runs[run]["limiting"], 0.0) + runs[run]["probability"] / total
        result["variants"].append({
            "label": label, "variables": assignment, "operability_percent": json_number(percent),
            "probability_total": total, "runs": len(members),
            "failed_runs": sum(1 for run in members if runs[run]["status"] != "complete"),
            "not_operable_probability_by_limiting_criterion": limiting,
            "cells": [{"run": runs[run]["run"], "Hs": runs[run]["Hs"], "Tp": runs[run]["Tp"],
                       "probability": runs[run]["probability"], "status": runs[run]["status"],
                       "operable": runs[run]["operable"], "limiting": runs[run]["limiting"],
                       "margins": {c.name: json_number(m) for c, m in zip(criteria, runs[run]["margins"])}}
                      for run in members]})
    return result


def plot(path, criteria, runs, variants, summary):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Patch

    names = [c.name for c in criteria]
    failures = sorted({runs[r]["limiting"] for _, _, members in variants for r in members if runs[r]["status"] != "complete"})
    palette = plt.get_cmap("tab10").colors
    colour = {name: palette[k % 10] for k, name in enumerate(names)}
    for k, status in enumerate(failures):
        colour[status] = (0.25 + 0.2 * (k % 3),) * 3  # greys: runs that did not complete
    panels = len(variants)
    figure, axes = plt.subplots(1, panels, figsize=(5.2 * panels + 1.0, 5.0), squeeze=False)
    for axis, (label, _, members), entry in zip(axes[0], variants, summary["variants"]):
        hs = sorted({runs[r]["Hs"] for r in members})
        tp = sorted({runs[r]["Tp"] for r in members})
        total = entry["probability_total"]
        for r in members:
            run = runs[r]
            i, j = hs.index(run["Hs"]), tp.index(run["Tp"])
            alpha = 0.3 if run["operable"] else 0.95
            axis.add_patch(plt.Rectangle((j - 0.5, i - 0.5), 1, 1, facecolor=colour[run["limiting"]], alpha=alpha,
                                         edgecolor="white", linewidth=1.5))
            share = 100 * run["probability"] / total
            share_text = "0" if share == 0 else ("<0.01%" if share < 0.01 else f"{share:.2f}%")
            axis.text(j, i + 0.12, share_text, ha="center", va="center", fontsize=7.5)
            axis.text(j, i - 0.2, "ok" if run["operable"] else "x", ha="center", va="center", fontsize=8,
                      fontweight="bold", color="black" if run["operable"] else "white")
        axis.set_xlim(-0.5, len(tp) - 0.5)
        axis.set_ylim(-0.5, len(hs) - 0.5)
        axis.set_xticks(range(len(tp)), [f"{t:g}" for t in tp])
        axis.set_yticks(range(len(hs)), [f"{h:g}" for h in hs])
        axis.set_xlabel("Tp [s]")
        axis.set_ylabel("Hs [m]")
        percent = entry["operability_percent"]
        axis.set_title(f"{label}\noperable {percent:.1f} % of the time" if percent is not None else label, fontsize=10)
    handles = [Patch(facecolor=colour[c.name], label=f"{c.name} ({c.limits()})") for c in criteria]
    handles += [Patch(facecolor=colour[status], label=f"run {status}") for status in failures]
    handles.append(Patch(facecolor="white", edgecolor="grey", label="pale: operable, tint = least margin"))
    figure.legend(handles=handles, loc="lower center", ncol=min(len(handles), 3), fontsize=8, frameon=False)
    figure.suptitle("Operability over the scatter diagram: cells coloured by the limiting criterion, occurrence in each cell",
                    fontsize=10)
    figure.tight_layout(rect=(0, 0.1, 1, 0.95))
    figure.savefig(path, dpi=110)
    plt.close(figure)


def main(argv=None):
    parser = argparse.ArgumentParser(prog="heavesim operability", description=__doc__.splitlines()[0])
    parser.add_argument("index", help="the sweep's index file (HDF5)")
    parser.add_argument("--criteria", required=True, help="criteria file (YAML)")
    parser.add_argument("-o", "--output", help="directory of operability.csv/.json/.png (default: the index's)")
    parser.add_argument("--json", action="store_true", help="print the JSON summary instead of the table")
    arguments = parser.parse_args(argv)
    try:
        index = Index(arguments.index)
        criteria = load_criteria(arguments.criteria, index)
    except InputError as error:
        print(f"heavesim: bad input: {error}", file=sys.stderr)
        return 2

    runs = evaluate(index, criteria)
    variants = variants_of(index)
    variant_of_run = {run: label for label, _, members in variants for run in members}
    summary = summary_of(index, criteria, runs, variants)
    directory = arguments.output or os.path.dirname(os.path.abspath(arguments.index))
    try:
        os.makedirs(directory, exist_ok=True)
        write_csv(os.path.join(directory, "operability.csv"), criteria, runs, variant_of_run)
        with open(os.path.join(directory, "operability.json"), "w") as f:
            json.dump(summary, f, indent=1)
        plot(os.path.join(directory, "operability.png"), criteria, runs, variants, summary)
    except OSError as error:
        print(f"heavesim: error: {error.filename}: {error.strerror}", file=sys.stderr)
        return 1

    if arguments.json:
        json.dump(summary, sys.stdout, indent=1)
        print()
        return 0
    print(f"operability of {index.count} runs in {arguments.index} ({len(criteria)} criteria; "
          f"{directory}/operability.csv, .json, .png)")
    for entry in summary["variants"]:
        limiting = ", ".join(f"{name} {100 * p:.1f} %" for name, p in
                             sorted(entry["not_operable_probability_by_limiting_criterion"].items(), key=lambda item: -item[1]))
        percent = entry["operability_percent"]
        print(f"  {entry['label']}: operable {percent:.1f} % of the time ({entry['runs']} sea states, "
              f"{entry['failed_runs']} failed runs); not operable: {limiting or 'never'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
