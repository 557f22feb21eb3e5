#!/usr/bin/python3
"""Differences between two heavesim result files of the same case (a run against a
tight-tolerance reference), over the samples both files have. For the drilling rig:
the load's heave (bodies/drill_string/position z) and the hook load (the vertical reaction
at the top-drive/string joint, joints/td_string/reaction_force z: docs/result-file.md,
"Design quantities"), plus each file's compensation efficiency. For any other case: the
largest difference of every channel both files record.

  /usr/bin/python3 scripts/compare_runs.py reference.h5 run.h5
  /usr/bin/python3 scripts/compare_runs.py --every-number before.h5 after.h5

Reads the files with the heavesim package (docs/python.md): run it after the build.
--every-number instead compares every floating-point dataset and attribute the two files
share (the fields of compound attributes too, so every recorded statistic) and lists those
that differ at all, with their largest difference: the check that a change meant to
leave results alone (a faster path, a second thread) left them bitwise alone. The run's
own wall time and real-time factor (/summary) always differ.
"""
import argparse
import pathlib
import sys

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import heavesim  # noqa: E402  the repository's heavesim.py: the package in build/python

def drilling_series(r):
    """(label, values, units) of the rig's load heave and hook load, those the file has."""
    series = []
    if "bodies/drill_string/position" in r:
        series.append(("load heave", r["bodies/drill_string/position"][:, 2], "m"))
    if "joints/td_string/reaction_force" in r:
        series.append(("hook load", r["joints/td_string/reaction_force"][:, 2], "N"))
    return series


def describe(label, ref, run, units):
    difference = run - ref
    print(f"{label}: max |difference| {np.max(np.abs(difference)):.3g} {units}, "
          f"RMS difference {np.sqrt(np.mean(difference ** 2)):.3g} {units} "
          f"(reference: std {np.std(ref):.4g} {units}, peak-to-peak {np.ptp(ref):.4g} {units})")


def differing_numbers(reference_path, run_path):
    """{name: largest |difference|} of every floating-point dataset or attribute (compound
    fields included, by name; name@attribute for an attribute) that differs between the two
    files; inf where the shapes or a compound's set of fields differ."""
    import h5py
    differences = {}

    def compare(name, x, y):
        x, y = np.asarray(x), np.asarray(y)
        if x.dtype.names or y.dtype.names:
            # Compound records: field by field, by name (their order in the type may differ
            # between versions); another set of fields or shape is a difference.
            if x.shape != y.shape or sorted(x.dtype.names or ()) != sorted(y.dtype.names or ()):
                differences[name] = float("inf")
                return
            for field in x.dtype.names:
                compare(f"{name}.{field}", x[field], y[field])
        elif x.dtype.kind == "f" and x.shape == y.shape and x.size:
            same = (x == y) | (np.isnan(x) & np.isnan(y))
            if not same.all():
                differences[name] = np.nanmax(np.abs(x - y))
        elif x.dtype.kind == "f" and x.shape != y.shape:
            differences[name] = float("inf")

    with h5py.File(reference_path, "r") as reference, h5py.File(run_path, "r") as run:
        def visit(name, item):
            if name not in run:
                return
            if isinstance(item, h5py.Dataset):
                compare(name, item[()], run[name][()])
            for key, value in item.attrs.items():
                if key in run[name].attrs:
                    compare(f"{name}@{key}", value, run[name].attrs[key])
        visit("/", reference["/"])
        reference.visititems(visit)
    return differences


def every_number(reference_path, run_path):
    """Prints every floating-point dataset or attribute that differs between the two
    files, and how many there are."""
    differences = differing_numbers(reference_path, run_path)
    for name, difference in sorted(differences.items()):
        print(f"{name}: max |difference| {difference:.3g}")
    print(f"{len(differences)} floating-point datasets or attributes differ")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("reference", help="the reference result file (HDF5)")
    parser.add_argument("run", help="the result file compared with it")
    parser.add_argument("--every-number", action="store_true",
                        help="list every floating-point dataset or attribute that differs at all")
    args = parser.parse_args()
    if args.every_number:
        every_number(args.reference, args.run)
        return
    with heavesim.open(args.reference) as reference, heavesim.open(args.run) as run:
        t_ref, t_run = reference.time, run.time
        n = min(len(t_ref), len(t_run))
        if n == 0:
            sys.exit("compare_runs: a file holds no samples")
        if not np.allclose(t_ref[:n], t_run[:n]):
            sys.exit("the two files do not share their output times")
        pairs = list(zip(drilling_series(reference), drilling_series(run)))
        if pairs:
            for (label, ref, units), (_, values, _) in pairs:
                describe(label, ref[:n], values[:n], units)
        else:
            for path in sorted(set(reference.channels) & set(run.channels)):
                describe(path, reference[path][:n], run[path][:n], reference.channels[path].units)
        eta_ref = {k: v for k, v in reference.summary.items() if k.endswith("_efficiency")}
        eta_run = {k: v for k, v in run.summary.items() if k.endswith("_efficiency")}
        for key in sorted(eta_ref):
            print(f"{key}: reference {eta_ref[key]:.5f}, run {eta_run.get(key, float('nan')):.5f}")
        print(f"steps: reference {reference.summary.get('integrator_steps')}, run {run.summary.get('integrator_steps')}; "
              f"samples compared {n} (to t = {t_ref[n - 1]:g} s)")


if __name__ == "__main__":
    main()
