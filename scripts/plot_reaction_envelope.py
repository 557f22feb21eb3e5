#!/usr/bin/python3
"""Per-joint reaction envelope of a heavesim result file, the structural deliverable:
for every joint, the range (minimum to maximum over the record, or over t >= --from)
of each reaction force and moment component in the joint's own frame
(`reaction_force_joint`, `reaction_moment_joint`: the wrench the parent passes to the
child at the joint origin, docs/result-file.md), one panel per joint. Each bar is the
dynamic range about the component's mean (the mean under its name), on axes in N, kN or
MN by the size of the range, so that a 2.6 MN static load's ±600 N is seen; forces on the
left axis, moments on the right. Joints whose largest load is below 1e-6 of the file's
largest carry nothing and are left out (named in the title). Writes
<out>/<stem>_reaction_envelope.png and <out>/<stem>_reaction_envelope.csv (min, mean, max).

    /usr/bin/python3 scripts/plot_reaction_envelope.py results/drilling.h5 -o results [--from 300]
    [--skip heave]   # leave out joints (e.g. a prescribed platform joint carrying the hull)

Run it with Debian's /usr/bin/python3 (numpy, h5py, matplotlib from python3-*) after the
build: it reads result files with the heavesim package (docs/python.md).
"""
import argparse
import csv
import math
import os
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import heavesim  # noqa: E402  the repository's heavesim.py: the package in build/python
from plot_run import NOTHING, engineering_scale, si  # noqa: E402  one set of plotting rules

COMPONENTS = ["Fx", "Fy", "Fz", "Mx", "My", "Mz"]


def envelopes(r, start, skip):
    window = r.time >= start
    rows = []
    for name in r.joints:
        if name in skip or f"joints/{name}/reaction_force_joint" not in r:
            continue
        wrench = np.hstack([r[f"joints/{name}/reaction_force_joint"][window],
                            r[f"joints/{name}/reaction_moment_joint"][window]])
        rows.append((name, wrench.min(axis=0), wrench.mean(axis=0), wrench.max(axis=0)))
    return rows


def plot_envelope(r, out, stem, start=-math.inf, skip=()):
    """Writes <out>/<stem>_reaction_envelope.png and .csv for the open result `r` (a
    heavesim.Result); returns (png path, csv path), or None when no joint reaction is
    recorded. `start`: window start [s]; `skip`: joint names to leave out."""
    every = envelopes(r, start, set(skip))
    if not every:
        return None
    scale = max(np.abs(np.concatenate([low[:3], high[:3]])).max() for _, low, _, high in every)
    rows = [row for row in every if np.abs(np.concatenate([row[1][:3], row[3][:3]])).max() > NOTHING * scale]
    idle = sorted({row[0] for row in every} - {row[0] for row in rows})

    csv_path = os.path.join(out, f"{stem}_reaction_envelope.csv")
    units = ["N"] * 3 + ["N m"] * 3
    with open(csv_path, "w", newline="") as table:
        writer = csv.writer(table)
        writer.writerow(["joint"] + [f"{c}_{end} [{u}]" for c, u in zip(COMPONENTS, units) for end in ("min", "mean", "max")])
        for name, low, mean, high in every:
            writer.writerow([name] + [f"{v:.6e}" for triple in zip(low, mean, high) for v in triple])

    columns = min(3, len(rows))
    lines = math.ceil(len(rows) / columns)
    fig, axes = plt.subplots(lines, columns, figsize=(5.2 * columns, 3.6 * lines + 0.6), squeeze=False)
    for ax, (name, low, mean, high) in zip(axes.flat, rows):
        moments = ax.twinx()
        for target, part, color, unit in ((ax, slice(0, 3), "C0", "N"), (moments, slice(3, 6), "C1", "N m")):
            below, above = (low - mean)[part], (high - mean)[part]
            factor, label = engineering_scale(unit, max(np.abs(np.concatenate([below, above])).max(), 1e-300))
            positions = np.arange(6)[part]
            target.bar(positions, (above - below) / factor, bottom=below / factor, color=color, width=0.6)
            for k, lo, hi in zip(positions, below, above):
                target.annotate(f"{hi / factor:+.3g}", (k, hi / factor), textcoords="offset points", xytext=(0, 2),
                                ha="center", fontsize=7)
                target.annotate(f"{lo / factor:+.3g}", (k, lo / factor), textcoords="offset points", xytext=(0, -9),
                                ha="center", fontsize=7)
            target.set_ylabel(f"{'force' if unit == 'N' else 'moment'} − mean [{label}]", color=color)
            target.margins(y=0.3)
        ax.axhline(0.0, color="grey", linewidth=0.6)
        ax.set_xticks(np.arange(6), [f"{c}\n{si(m, u)}" for c, m, u in zip(COMPONENTS, mean, units)], fontsize=7)
        ax.set_title(name)
        ax.grid(True, axis="y", alpha=0.3)
    for ax in list(axes.flat)[len(rows):]:
        ax.axis("off")
    window = "" if math.isinf(start) else f", t >= {start:g} s"
    title = f"{stem}: joint reaction envelopes, joint frames: min to max about the mean (mean under each name){window}"
    if idle:
        title += "\ncarry nothing (< 1e-6 of the largest load), not drawn: " + ", ".join(idle)
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    png_path = os.path.join(out, f"{stem}_reaction_envelope.png")
    fig.savefig(png_path, dpi=110)
    plt.close(fig)
    return png_path, csv_path


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("result")
    parser.add_argument("-o", "--output", default="results")
    parser.add_argument("--from", dest="start", type=float, default=-math.inf, help="window start [s]")
    parser.add_argument("--skip", nargs="*", default=[], help="joints to leave out")
    args = parser.parse_args()
    stem = os.path.splitext(os.path.basename(args.result))[0]
    os.makedirs(args.output, exist_ok=True)
    with heavesim.open(args.result) as r:
        written = plot_envelope(r, args.output, stem, args.start, args.skip)
    if written is None:
        raise SystemExit(f"{args.result}: no joint reactions recorded (output.channels must include reactions)")
    print(f"wrote {written[0]} and {written[1]}")


if __name__ == "__main__":
    main()
