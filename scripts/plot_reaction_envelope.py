#!/usr/bin/python3
"""Per-joint reaction envelope of a heavesim result file, the structural deliverable:
for every joint, the range (minimum to maximum over the record, or over t >= --from)
of each reaction force and moment component in the joint's own frame
(`reaction_force_joint`, `reaction_moment_joint`: the wrench the parent passes to the
child at the joint origin, docs/result-file.md), one panel per joint. Writes
<out>/<stem>_reaction_envelope.png and <out>/<stem>_reaction_envelope.csv.

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

COMPONENTS = ["Fx", "Fy", "Fz", "Mx", "My", "Mz"]


def envelopes(r, start, skip):
    window = r.time >= start
    rows = []
    for name in r.joints:
        if name in skip or f"joints/{name}/reaction_force_joint" not in r:
            continue
        wrench = np.hstack([r[f"joints/{name}/reaction_force_joint"][window],
                            r[f"joints/{name}/reaction_moment_joint"][window]])
        rows.append((name, wrench.min(axis=0), wrench.max(axis=0)))
    return rows


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
        rows = envelopes(r, args.start, set(args.skip))
    if not rows:
        raise SystemExit(f"{args.result}: no joint reactions recorded (output.channels must include reactions)")

    csv_path = os.path.join(args.output, f"{stem}_reaction_envelope.csv")
    with open(csv_path, "w", newline="") as out:
        writer = csv.writer(out)
        writer.writerow(["joint"] + [f"{c}_{end}" for c in COMPONENTS for end in ("min", "max")])
        for name, low, high in rows:
            writer.writerow([name] + [f"{v:.6e}" for pair in zip(low, high) for v in pair])

    columns = min(3, len(rows))
    lines = math.ceil(len(rows) / columns)
    fig, axes = plt.subplots(lines, columns, figsize=(4.6 * columns, 3.4 * lines), squeeze=False)
    for ax, (name, low, high) in zip(axes.flat, rows):
        positions = np.arange(6)
        scale = np.array([1e-6] * 3 + [1e-6] * 3)
        ax.bar(positions, (high - low) * scale, bottom=low * scale, color=["C0"] * 3 + ["C1"] * 3, width=0.6)
        largest = max(np.abs(np.concatenate([low, high])).max() * 1e-6, 1e-12)
        for k in positions:
            ax.plot([k - 0.3, k + 0.3], [high[k] * scale[k]] * 2, color="k", linewidth=0.8)
            ax.plot([k - 0.3, k + 0.3], [low[k] * scale[k]] * 2, color="k", linewidth=0.8)
            if max(abs(low[k]), abs(high[k])) * 1e-6 > 1e-3 * largest:
                # The range in numbers: a static load makes the bar itself thin.
                ax.annotate(f"{low[k] * scale[k]:.4g}\n…{high[k] * scale[k]:.4g}", (k, high[k] * scale[k]),
                            textcoords="offset points", xytext=(0, 3), ha="center", fontsize=7)
        ax.axhline(0.0, color="grey", linewidth=0.6)
        ax.set_xticks(positions, COMPONENTS)
        ax.set_title(name)
        ax.set_ylabel("force [MN] / moment [MN m]")
        ax.grid(True, axis="y", alpha=0.3)
        ax.margins(y=0.25)
    for ax in list(axes.flat)[len(rows):]:
        ax.axis("off")
    window = "" if math.isinf(args.start) else f", t >= {args.start:g} s"
    fig.suptitle(f"{stem}: joint reaction envelopes, joint frames (min to max{window})")
    fig.tight_layout()
    png_path = os.path.join(args.output, f"{stem}_reaction_envelope.png")
    fig.savefig(png_path, dpi=110)
    print(f"wrote {png_path} and {csv_path}")


if __name__ == "__main__":
    main()
