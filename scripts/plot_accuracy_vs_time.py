#!/usr/bin/python3
"""Work-precision diagram from bench/accuracy_vs_time's CSV: error against the
independent reference versus CPU time, one panel per problem, one line per integrator
(and linear solver) over its tolerances or steps. Failed runs (no error) are listed
under the panel instead of plotted.

    build/bench/heavesim_accuracy_vs_time results/accuracy_vs_time.csv
    /usr/bin/python3 scripts/plot_accuracy_vs_time.py results/accuracy_vs_time.csv -o docs/figures/work_precision.png

Run it with Debian's /usr/bin/python3 (numpy, matplotlib from python3-*).
"""
import argparse
import csv
import math
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

TITLES = {
    "double_pendulum": "double pendulum, 10 s from horizontal",
    "three_link": "3-link pendulum, 5 s from horizontal",
    "slider_crank": "slider-crank (idaSlCrank), 10 s",
    "four_bar": "four-bar A02 N = 1, 10 s (singular passes)",
    "a01_pendulum": "IFToMM A01 pendulum, 10 s: P1 x, y [m]",
    "a03_andrews": "IFToMM A03 Andrews, 0.03 s: mixed error 10^-mescd",
    "a04_bricard": "IFToMM A04 Bricard, 10 s: P3 [m]",
    "a05_governor": "IFToMM A05 flyball governor, 10 s: slider s [m]",
}
# Issue #3's targets: double pendulum to 1e-6 within 10 ms CPU.
TARGETS = {"double_pendulum": (1e-6, 1e-2)}


def read(path):
    rows = defaultdict(lambda: defaultdict(list))
    for row in csv.DictReader(open(path)):
        method = row["integrator"] + (f" ({row['linear_solver']})" if row["linear_solver"] else "")
        rows[row["problem"]][method].append(row)
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("csv")
    parser.add_argument("-o", "--output", default="work_precision.png")
    args = parser.parse_args()
    rows = read(args.csv)
    problems = [name for name in TITLES if name in rows] + [name for name in rows if name not in TITLES]
    columns = 2
    lines = math.ceil(len(problems) / columns)
    fig, axes = plt.subplots(lines, columns, figsize=(12, 5.2 * lines), squeeze=False)
    for ax, problem in zip(axes.flat, problems):
        failed = []
        for method, runs in sorted(rows[problem].items()):
            points = [(float(r["cpu_s"]), float(r["error"]), r["parameter"]) for r in runs
                      if r["error"] not in ("inf", "nan") and math.isfinite(float(r["error"])) and float(r["error"]) > 0]
            failed += [f"{method} {r['parameter_name']}={r['parameter']}" for r in runs if r["note"]]
            if not points:
                continue
            points.sort()
            marker = "*" if method.startswith("idaSlCrank") else "o"
            size = 14 if marker == "*" else 4
            ax.loglog([1e3 * p[0] for p in points], [p[1] for p in points], marker=marker, markersize=size,
                      label=method, linestyle="none" if len(points) == 1 else "-")
        if problem in TARGETS:
            error, cpu = TARGETS[problem]
            ax.axhline(error, color="grey", linestyle=":", linewidth=1)
            ax.axvline(1e3 * cpu, color="grey", linestyle=":", linewidth=1)
        ax.set_title(TITLES.get(problem, problem))
        units = next(iter(rows[problem].values()))[0]["error_units"]
        ax.set_xlabel("CPU time [ms]")
        ax.set_ylabel(f"max error vs reference [{units}]")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
        if failed:
            ax.text(0.01, 0.01, "failed: " + "; ".join(failed[:6]) + (" ..." if len(failed) > 6 else ""),
                    transform=ax.transAxes, fontsize=6, va="bottom", wrap=True)
    for ax in list(axes.flat)[len(problems):]:
        ax.axis("off")
    fig.tight_layout()
    fig.savefig(args.output, dpi=110)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
