#!/usr/bin/python3
"""Compensation efficiency against the wave period, for the compensation modes of
docs/physics/drilling-rig.md §6 (locked, passive, passive + active), on the H0 rig with the
default semi floating in regular head seas (case C3, a = 2 m, 600 s, 30 s ramp).

The study is the sweep cases/sweeps/compensation_study.yaml (3 modes x 6 periods); this
script runs it (`heavesim sweep ... -j <cores>`, resumed: runs already complete are not
run again) and plots its index. Over the window t >= 300 s of each run the index holds the
standard deviations of the drill string's and the platform's heights, and

    eta = 1 - std(z_string) / std(z_derrick)

(the derrick stands on the platform's z axis; with heave-only excitation roll and pitch
stay ~0). For a steady sinusoid the ratio of standard deviations is the amplitude ratio.
Writes <out>/efficiency_vs_period.csv (with the platform heave amplitude) and
<out>/efficiency_vs_period.png.

    /usr/bin/python3 scripts/compensation_study.py [-o results] [--binary build/heavesim] [--no-run]

Run it with Debian's /usr/bin/python3 (numpy, h5py, matplotlib from python3-*).
"""
import argparse
import csv
import os
import subprocess
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SWEEP = os.path.join(ROOT, "cases", "sweeps", "compensation_study.yaml")
MODES = {"locked": "locked", "passive": "passive", "active": "passive + active (force actuator)"}


def mode_of(base_case):
    name = os.path.basename(base_case)  # h0_<mode>.yaml
    return name[len("h0_"):-len(".yaml")]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--binary", default=os.path.join(ROOT, "build", "heavesim"))
    parser.add_argument("-o", "--output", default="results")
    parser.add_argument("--no-run", action="store_true", help="only plot an existing index")
    args = parser.parse_args()
    directory = os.path.join(args.output, "compensation_study")
    if not args.no_run:
        command = [args.binary, "sweep", SWEEP, "-o", directory, "-j", str(os.cpu_count() or 1), "-q"]
        result = subprocess.run(command)
        if result.returncode != 0:
            sys.exit(f"{' '.join(command)} failed ({result.returncode}); see {directory}/index.csv and logs/")

    with h5py.File(os.path.join(directory, "index.h5"), "r") as f:
        modes = [mode_of(path) for path in f["runs/base_case"].asstr()[:]]
        periods = f["variables/parameters.T"][:]
        # Column 2 of a body position is its height z.
        string = f["statistics/bodies.drill_string.position/window_standard_deviation"][:, 2]
        platform = f["statistics/bodies.platform.position/window_standard_deviation"][:, 2]
    table = {(mode, period): 1.0 - s / p for mode, period, s, p in zip(modes, periods, string, platform)}
    heave = {(mode, period): np.sqrt(2.0) * p for mode, period, p in zip(modes, periods, platform)}
    mode_list = [mode for mode in MODES if mode in modes]
    period_list = sorted(set(periods))
    for (mode, period), eta in table.items():
        print(f"{MODES[mode]:42s} T = {period:5.1f} s  platform heave {heave[mode, period]:.3f} m  efficiency {eta:.4f}")

    csv_path = os.path.join(args.output, "efficiency_vs_period.csv")
    with open(csv_path, "w", newline="") as out:
        writer = csv.writer(out)
        writer.writerow(["period_s"] + mode_list + [f"platform_heave_m_{mode}" for mode in mode_list])
        for period in period_list:
            writer.writerow([f"{period:g}"] + [f"{table[mode, period]:.6f}" for mode in mode_list] +
                            [f"{heave[mode, period]:.4f}" for mode in mode_list])

    fig, ax = plt.subplots(figsize=(7.5, 4.8))
    for mode in mode_list:
        ax.plot(period_list, [table[mode, period] for period in period_list], marker="o", label=MODES[mode])
    ax.axhspan(0.85, 0.90, color="C1", alpha=0.12, label="expected passive (docs/physics/drilling-rig.md §6)")
    ax.axhline(0.95, color="C2", linestyle=":", label="expected passive + active ≥ 0.95")
    ax.set_xlabel("wave period T [s]")
    ax.set_ylabel("efficiency 1 − σ(z_string) / σ(z_derrick)")
    ax.set_title("H0 rig on the default semi floating in regular waves, a = 2 m")
    ax.set_ylim(min(-0.05, min(table.values()) - 0.05), 1.02)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8, loc="center right")
    fig.tight_layout()
    png_path = os.path.join(args.output, "efficiency_vs_period.png")
    fig.savefig(png_path, dpi=110)
    print(f"wrote {png_path} and {csv_path}")


if __name__ == "__main__":
    main()
