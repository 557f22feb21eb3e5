#!/usr/bin/python3
"""Plots a heavesim result file: joint coordinates and speeds, joint reaction forces
and moments, and energy, one PNG each.

    /usr/bin/python3 scripts/plot_run.py results/two_link.h5 [-o results]

Run it with Debian's /usr/bin/python3 (numpy, h5py, matplotlib from python3-*) after
the build: it reads the file with the heavesim package (docs/python.md).
"""
import argparse
import os
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import heavesim  # noqa: E402  the repository's heavesim.py: the package in build/python


def label(channel, name):
    return f"{name} [{channel.units}]" if channel.units else name


def save(fig, out, stem, kind):
    """Writes out/<stem>_<kind>.png and returns its path."""
    path = os.path.join(out, f"{stem}_{kind}.png")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path


def plot_joints(r, time, stem, out):
    joints = [name for name in r.joints if f"joints/{name}/q" in r]
    if not joints:
        return None
    fig, (ax_q, ax_v) = plt.subplots(2, 1, sharex=True, figsize=(9, 6.5))
    for name in joints:
        q, qd = r[f"joints/{name}/q"], r[f"joints/{name}/qd"]
        for c in range(q.shape[1]):
            ax_q.plot(time, q[:, c], label=f"{name}" + (f"[{c}]" if q.shape[1] > 1 else ""))
        for c in range(qd.shape[1]):
            ax_v.plot(time, qd[:, c], label=f"{name}" + (f"[{c}]" if qd.shape[1] > 1 else ""))
    ax_q.set_ylabel(label(r.channel(f"joints/{joints[0]}/q"), "joint coordinate"))
    ax_v.set_ylabel(label(r.channel(f"joints/{joints[0]}/qd"), "joint speed"))
    ax_v.set_xlabel("time [s]")
    ax_q.set_title(f"{stem}: joint coordinates (relative angles) and speeds")
    for ax in (ax_q, ax_v):
        ax.grid(True, alpha=0.3)
        ax.legend(loc="upper right", fontsize=8)
    return save(fig, out, stem, "joints")


def plot_reactions(r, time, stem, out):
    joints = [name for name in r.joints if f"joints/{name}/reaction_force" in r]
    if not joints:
        return None
    fig, axes = plt.subplots(len(joints), 2, sharex=True, figsize=(11, 2.6 * len(joints)), squeeze=False)
    for row, name in enumerate(joints):
        force, moment = r.channel(f"joints/{name}/reaction_force"), r.channel(f"joints/{name}/reaction_moment")
        for c, axis in enumerate("xyz"):
            axes[row, 0].plot(time, force.values[:, c], label=f"F{axis}")
            axes[row, 1].plot(time, moment.values[:, c], label=f"M{axis}")
        axes[row, 0].plot(time, np.linalg.norm(force.values, axis=1), "k--", lw=0.8, label="|F|")
        axes[row, 0].set_ylabel(f"{name}\n" + label(force, "force"))
        axes[row, 1].set_ylabel(label(moment, "moment"))
        for ax in axes[row]:
            ax.grid(True, alpha=0.3)
            ax.legend(loc="upper right", fontsize=7, ncol=4)
    axes[0, 0].set_title(f"{stem}: reaction force of parent on child, world axes")
    axes[0, 1].set_title("reaction moment about the joint origin, world axes")
    for ax in axes[-1]:
        ax.set_xlabel("time [s]")
    return save(fig, out, stem, "reactions")


def plot_energy(r, time, stem, out):
    if "signals/total_energy" not in r:
        return None
    kinetic, potential, total = (r[f"signals/{name}"] for name in ("kinetic_energy", "potential_energy", "total_energy"))
    fig, (ax_e, ax_d) = plt.subplots(2, 1, sharex=True, figsize=(9, 6))
    ax_e.plot(time, kinetic, label="kinetic")
    ax_e.plot(time, potential, label="potential")
    ax_e.plot(time, total, "k", label="total")
    ax_e.set_ylabel("energy [J]")
    ax_e.set_title(f"{stem}: energy")
    scale = max(abs(total[0]), np.max(kinetic), 1e-300)
    ax_d.plot(time, (total - total[0]) / scale)
    ax_d.set_ylabel("(E - E0) / max(|E0|, max T)")
    ax_d.set_xlabel("time [s]")
    for ax in (ax_e, ax_d):
        ax.grid(True, alpha=0.3)
    ax_e.legend(loc="upper right", fontsize=8)
    return save(fig, out, stem, "energy")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("result", help="heavesim HDF5 result file")
    parser.add_argument("-o", "--output", default=None, help="directory for the PNGs (default: next to the file)")
    args = parser.parse_args()
    out = args.output or os.path.dirname(os.path.abspath(args.result))
    os.makedirs(out, exist_ok=True)
    stem = os.path.splitext(os.path.basename(args.result))[0]
    with heavesim.open(args.result) as r:
        if not r.complete:
            print(f"plot_run: note: {args.result} is marked incomplete (complete = 0); plotting what it holds")
        time = r.time
        written = [plot(r, time, stem, out) for plot in (plot_joints, plot_reactions, plot_energy)]
    for path in filter(None, written):
        print(f"plot_run: wrote {path}")


if __name__ == "__main__":
    main()
