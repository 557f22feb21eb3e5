#!/usr/bin/python3
"""Differences between two heavesim result files of the same case (a run against a
tight-tolerance reference), over the samples both files have. For the drilling rig:
the load's heave (bodies/drill_string/position z) and the hook load (the vertical reaction
at the top-drive/string joint, joints/td_string/reaction_force z: docs/result-file.md,
"Design quantities"), plus each file's compensation efficiency. For any other case: the
largest difference of every channel both files record.

  /usr/bin/python3 scripts/compare_runs.py reference.h5 run.h5

Reads the files with the heavesim package (docs/python.md): run it after the build.
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


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("reference", help="the reference result file (HDF5)")
    parser.add_argument("run", help="the result file compared with it")
    args = parser.parse_args()
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
