#!/usr/bin/python3
"""Differences between two heavesim result files of the same case (a run against a
tight-tolerance reference): the load's heave (bodies/drill_string/position z) and the
hook load (the sum of the compensator forces on the crown block, forces/*/force of the
passive and active compensators), over the samples both files have, plus each file's
compensation efficiency.

  /usr/bin/python3 scripts/compare_runs.py reference.h5 run.h5
"""
import sys

import h5py
import numpy as np

COMPENSATORS = ("passive_a", "passive_b", "passive", "active")


def series(path):
    with h5py.File(path, "r") as f:
        time = f["time"][:]
        heave = f["bodies/drill_string/position"][:, 2]
        hook = sum(f[f"forces/{name}/force"][:] for name in COMPENSATORS if f"forces/{name}/force" in f)
        efficiency = {key: value for key, value in f["summary"].attrs.items() if key.endswith("_efficiency")}
        steps = f["summary"].attrs.get("integrator_steps")
    return time, heave, hook, efficiency, steps


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    t_ref, heave_ref, hook_ref, eta_ref, steps_ref = series(sys.argv[1])
    t_run, heave_run, hook_run, eta_run, steps_run = series(sys.argv[2])
    n = min(len(t_ref), len(t_run))
    if not np.allclose(t_ref[:n], t_run[:n]):
        sys.exit("the two files do not share their output times")
    for label, ref, run, units in (("load heave", heave_ref, heave_run, "m"), ("hook load", hook_ref, hook_run, "N")):
        difference = run[:n] - ref[:n]
        print(f"{label}: max |difference| {np.max(np.abs(difference)):.3g} {units}, "
              f"RMS difference {np.sqrt(np.mean(difference ** 2)):.3g} {units} "
              f"(reference: std {np.std(ref[:n]):.4g} {units}, peak-to-peak {np.ptp(ref[:n]):.4g} {units})")
    for key in sorted(eta_ref):
        print(f"{key}: reference {eta_ref[key]:.5f}, run {eta_run.get(key, float('nan')):.5f}")
    print(f"steps: reference {steps_ref}, run {steps_run}; samples compared {n} (to t = {t_ref[n - 1]:g} s)")


if __name__ == "__main__":
    main()
