#!/usr/bin/python3
"""Compensation efficiency against the wave period, for the compensation modes of
docs/physics/drilling-rig.md §6 (locked, passive, passive + active), on the H0 rig with the
default semi floating in regular head seas (case C3: cases/c3_regular_waves/h0_<mode>.yaml,
a = 2 m, 600 s, 30 s ramp). Runs heavesim once per mode and period (in parallel, one
run per core) and takes, over the last 300 s of each record,

    eta = 1 - std(z_string) / std(z_derrick)

from the recorded heights of the drill string and the platform origin (the derrick
stands on the platform's z axis; with heave-only excitation roll and pitch stay ~0).
For a steady sinusoid the ratio of standard deviations is the amplitude ratio. Writes
<out>/efficiency_vs_period.csv (with the platform heave amplitude) and
<out>/efficiency_vs_period.png.

    /usr/bin/python3 scripts/compensation_study.py [--amplitude 2] [--periods 6 8 10 12 14 16] [-o results]

Run it with Debian's /usr/bin/python3 (numpy, h5py, matplotlib from python3-*) after the
build: it reads result files with the heavesim package (docs/python.md).
"""
import argparse
import concurrent.futures
import csv
import os
import pathlib
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import heavesim  # noqa: E402  the repository's heavesim.py: the package in build/python

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MODES = {"locked": "locked", "passive": "passive", "active": "passive + active (force actuator)",
         "active_hydraulic": "passive + active (servo valve, cylinder)"}


def efficiency(path):
    """(eta, platform heave amplitude [m]) over the last 300 s."""
    with heavesim.open(path) as r:
        time = r.time
        window = time >= time[-1] - 300.0
        platform = r["bodies/platform/position"][:, 2][window]
        string = r["bodies/drill_string/position"][:, 2][window]
    return 1.0 - np.std(string) / np.std(platform), np.sqrt(2.0) * np.std(platform)


def run(binary, mode, period, amplitude, path):
    command = [binary, "run", os.path.join(ROOT, "cases", "c3_regular_waves", f"h0_{mode}.yaml"),
               "-o", path, "--quiet", "--set", f"parameters.T={period:g}",
               "--set", f"parameters.a={amplitude:g}", "--set", "output.channels=[bodies]"]
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"{' '.join(command)} failed ({result.returncode}):\n{result.stdout}{result.stderr}")
    return efficiency(path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--amplitude", type=float, default=2.0, help="wave amplitude a [m]")
    parser.add_argument("--periods", type=float, nargs="+", default=[6, 8, 10, 12, 14, 16])
    parser.add_argument("--modes", nargs="+", default=["locked", "passive", "active"], choices=list(MODES))
    parser.add_argument("--binary", default=os.path.join(ROOT, "build", "heavesim"))
    parser.add_argument("-o", "--output", default="results")
    args = parser.parse_args()
    runs = os.path.join(args.output, "compensation_study")
    os.makedirs(runs, exist_ok=True)

    jobs = {}
    with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 1) as pool:
        for mode in args.modes:
            for period in args.periods:
                path = os.path.join(runs, f"h0_{mode}_T{period:g}.h5")
                jobs[mode, period] = pool.submit(run, args.binary, mode, period, args.amplitude, path)
    table, heave = {}, {}
    for (mode, period), job in jobs.items():
        table[mode, period], heave[mode, period] = job.result()
        print(f"{MODES[mode]:42s} T = {period:5.1f} s  platform heave {heave[mode, period]:.3f} m  "
              f"efficiency {table[mode, period]:.4f}")

    csv_path = os.path.join(args.output, "efficiency_vs_period.csv")
    with open(csv_path, "w", newline="") as out:
        writer = csv.writer(out)
        writer.writerow(["period_s"] + args.modes + [f"platform_heave_m_{mode}" for mode in args.modes])
        for period in args.periods:
            writer.writerow([f"{period:g}"] + [f"{table[mode, period]:.6f}" for mode in args.modes] +
                            [f"{heave[mode, period]:.4f}" for mode in args.modes])

    fig, ax = plt.subplots(figsize=(7.5, 4.8))
    for mode in args.modes:
        ax.plot(args.periods, [table[mode, period] for period in args.periods], marker="o", label=MODES[mode])
    ax.axhspan(0.85, 0.90, color="C1", alpha=0.12, label="expected passive (docs/physics/drilling-rig.md §6)")
    ax.axhline(0.95, color="C2", linestyle=":", label="expected passive + active ≥ 0.95")
    ax.set_xlabel("wave period T [s]")
    ax.set_ylabel("efficiency 1 − σ(z_string) / σ(z_derrick)")
    ax.set_title(f"H0 rig on the default semi floating in regular waves, a = {args.amplitude:g} m")
    ax.set_ylim(min(-0.05, min(table.values()) - 0.05), 1.02)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8, loc="center right")
    fig.tight_layout()
    png_path = os.path.join(args.output, "efficiency_vs_period.png")
    fig.savefig(png_path, dpi=110)
    print(f"wrote {png_path} and {csv_path}")


if __name__ == "__main__":
    main()
