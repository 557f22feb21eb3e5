#!/usr/bin/python3
"""Plots a heavesim result file for an engineer: joint coordinates and speeds (one axis
per unit), the loads every joint, loop, driver and contact carries (the dynamic part of large
loads made visible, joints that carry nothing left out), and energy, one PNG each.

    /usr/bin/python3 scripts/plot_run.py results/two_link.h5 [-o results]

Rules (issue #16, docs/result-file.md for the quantities):
  * one axis per unit: metres, radians and their rates never share an axis; a free or
    spherical joint's quaternion is drawn as its rotation vector (rad, small-angle roll,
    pitch, yaw);
  * a load component whose mean is over 5 standard deviations is drawn as its variation
    about the mean, and the mean is written in its legend entry, so that a 2.6 MN load
    that moves by 600 N shows its 600 N;
  * a joint, loop or driver whose largest force is below 1e-6 of the largest in the file
    carries nothing: it is listed in the title, not drawn;
  * force axes in N, kN or MN by the size of what they show;
  * energy: with force elements or drivers doing work, kinetic + potential changes by
    their work and is drawn as such, not as a drift.

Run it with Debian's /usr/bin/python3 (numpy, h5py, matplotlib from python3-*) after
the build: it reads the file with the heavesim package (docs/python.md).
"""
import argparse
import os
import pathlib
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import yaml  # noqa: E402  the resolved case the file holds (/case/yaml)

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import heavesim  # noqa: E402  the repository's heavesim.py: the package in build/python

NOTHING = 1e-6  # a load below this fraction of the file's largest is "carries nothing"
MEAN_REMOVED = 5.0  # |mean| / std above which a component is drawn about its mean


def save(fig, out, stem, kind):
    """Writes out/<stem>_<kind>.png and returns its path."""
    path = os.path.join(out, f"{stem}_{kind}.png")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path


def engineering_scale(unit, magnitude):
    """(factor, label) so that magnitude / factor is in 0.1 .. 1000: N, kN, MN (and N m)."""
    if not unit.startswith("N"):
        return 1.0, unit
    for factor, prefix in ((1e6, "M"), (1e3, "k")):
        if magnitude >= 0.5 * factor:
            return factor, prefix + unit
    return 1.0, unit


def si(value, unit):
    factor, label = engineering_scale(unit, abs(value))
    return f"{value / factor:.4g} {label}"


# --- joint coordinates ------------------------------------------------------------------

def column_units(units, columns):
    """The unit of each column of a joint channel from its `units` attribute: one unit
    for all ("m"), one per column ("m, rad"), one per equal block of columns ("rad/s, m/s"
    on a free joint's six speeds), or a quaternion joint's "m, - (x, y, z, quaternion w, x, y, z)"."""
    if "quaternion" in units:
        translations = 3 if units.startswith("m") else 0
        return ["m"] * translations + ["quaternion"] * (columns - translations)
    parts = [p.strip() for p in re.sub(r"\(.*\)", "", units).split(",") if p.strip()]
    if parts and columns % len(parts) == 0:
        # "rad/s, m/s" on a free joint's six speeds: the angular block, then the linear one.
        return [part for part in parts for _ in range(columns // len(parts))]
    return [units or "-"] * columns


def rotation_vector(quaternion):
    """(N, 3) rotation vectors [rad] of unit quaternions (w, x, y, z): roll, pitch, yaw
    for small angles."""
    w = np.clip(quaternion[:, 0], -1.0, 1.0)
    vector = quaternion[:, 1:4]
    sine = np.linalg.norm(vector, axis=1)
    angle = 2.0 * np.arctan2(sine, w)
    with np.errstate(invalid="ignore", divide="ignore"):
        factor = np.where(sine > 1e-12, angle / sine, 2.0)
    return vector * factor[:, None]


def coordinate_curves(r, name, kind):
    """{unit: [(label, values)]} of joint `name`'s `q` or `qd`."""
    channel = r.channel(f"joints/{name}/{kind}")
    values = channel.values
    units = column_units(channel.units, values.shape[1])
    curves = {}
    if kind == "q" and "quaternion" in units:
        first = units.index("quaternion")
        for c in range(first):
            curves.setdefault(units[c], []).append((f"{name} {'xyz'[c]}", values[:, c]))
        rotation = rotation_vector(values[:, first:first + 4])
        for c, axis in enumerate(("roll", "pitch", "yaw")):
            curves.setdefault("rad", []).append((f"{name} {axis}", rotation[:, c]))
        return curves
    for c, unit in enumerate(units):
        curves.setdefault(unit, []).append((f"{name}" + (f"[{c}]" if values.shape[1] > 1 else ""), values[:, c]))
    return curves


def plot_joints(r, time, stem, out):
    joints = [name for name in r.joints if f"joints/{name}/q" in r]
    if not joints:
        return None
    rows = []
    for kind, what in (("q", "coordinate"), ("qd", "speed")):
        grouped = {}
        for name in joints:
            if f"joints/{name}/{kind}" not in r:
                continue
            for unit, curves in coordinate_curves(r, name, kind).items():
                grouped.setdefault(unit, []).extend(curves)
        rows += [(what, unit, curves) for unit, curves in grouped.items()]
    fig, axes = plt.subplots(len(rows), 1, sharex=True, figsize=(9, 2.4 * len(rows) + 0.8), squeeze=False)
    for ax, (what, unit, curves) in zip(axes[:, 0], rows):
        for label, values in curves:
            ax.plot(time, values, label=label)
        ax.set_ylabel(f"joint {what} [{unit}]")
        ax.grid(True, alpha=0.3)
        ax.legend(loc="upper right", fontsize=7, ncol=min(4, len(curves)))
    axes[0, 0].set_title(f"{stem}: joint coordinates and speeds (relative to the parent; one axis per unit)")
    axes[-1, 0].set_xlabel("time [s]")
    return save(fig, out, stem, "joints")


# --- loads ------------------------------------------------------------------------------

CONTACT_KINDS = ("ground_contact",)  # force kinds whose load is a contact force (app/forces)


def case_model(r):
    """The resolved case the file holds (/case/yaml: the model as the run read it) as a
    dict, or {}."""
    try:
        case = yaml.safe_load(r.case_yaml or "") or {}
    except yaml.YAMLError:
        return {}
    return case if isinstance(case, dict) else {}


def contact_elements(r):
    """The names of the case's contact force elements."""
    return [force["name"] for force in case_model(r).get("forces", [])
            if isinstance(force, dict) and force.get("type") in CONTACT_KINDS and "name" in force]


def load_sources(r):
    """[(title, force channel or None, moment channel or None)] for every tree joint, loop
    (constraint with a reaction), driver and contact element in the file."""
    sources = []
    for name in r.joints:
        if f"joints/{name}/reaction_force" in r:
            sources.append((f"joint {name}", r.channel(f"joints/{name}/reaction_force"),
                            r.channel(f"joints/{name}/reaction_moment")))
    for path in sorted(channel.lstrip("/") for channel in r.channels):
        match = re.fullmatch(r"constraints/([^/]+)/reaction_force", path)
        if match:
            moment = f"constraints/{match.group(1)}/reaction_moment"
            sources.append((f"loop {match.group(1)}", r.channel(path), r.channel(moment) if moment in r else None))
        match = re.fullmatch(r"drivers/([^/]+)/(force|torque)", path)
        if match:
            channel = r.channel(path)
            sources.append((f"driver {match.group(1)}", channel if match.group(2) == "force" else None,
                            channel if match.group(2) == "torque" else None))
    for name in contact_elements(r):
        if f"forces/{name}/force" in r:  # the normal force of the contact (e.g. weight on bit)
            sources.append((f"contact {name}", r.channel(f"forces/{name}/force"), None))
    # The case's `contacts` (rigid, by impulses): each pair's normal force and torsional
    # moment, each joint stop's force and each line's tension, from the element
    # "contacts" (docs/case-format.md, "contacts").
    for path in sorted(channel.lstrip("/") for channel in r.channels):
        if not path.startswith("forces/contacts/") or path.endswith("_friction_force"):
            continue
        match = re.fullmatch(r"forces/contacts/(.+)_normal_force", path) or \
            re.fullmatch(r"forces/contacts/(.+)_(?:force|tension)", path)
        if match:
            sources.append((f"contact {match.group(1)}", r.channel(path), None))
        torsion = re.fullmatch(r"forces/contacts/(.+)_torsion", path)
        if torsion:
            sources.append((f"contact {torsion.group(1)}", None, r.channel(path)))
    return sources


def largest(channel):
    if channel is None:
        return 0.0
    values = np.atleast_2d(channel.values.T).T
    return float(np.max(np.abs(values))) if values.size else 0.0


def draw_load(ax, time, channel, components):
    """Draws each component, about its mean where the mean dominates; the axis label
    says in which units."""
    values = np.atleast_2d(channel.values.T).T
    shown = []
    for c in range(values.shape[1]):
        column = values[:, c]
        mean, std = float(np.mean(column)), float(np.std(column))
        about_mean = abs(mean) > MEAN_REMOVED * std and std > 0.0
        shown.append((components[c] if values.shape[1] > 1 else "", column - mean if about_mean else column, mean,
                      about_mean))
    magnitude = max(float(np.max(np.abs(v))) for _, v, _, _ in shown) if shown else 0.0
    factor, unit = engineering_scale(channel.units, magnitude)
    any_about_mean = any(about for *_, about in shown)
    for label, values_shown, mean, about_mean in shown:
        legend = f"{label} − {si(mean, channel.units)}" if about_mean else label
        ax.plot(time, values_shown / factor, lw=0.9, label=legend or None)
    ax.set_ylabel(("variation " if any_about_mean else "") + f"[{unit}]")
    ax.grid(True, alpha=0.3)
    if any(label for label, *_ in shown) or any_about_mean:
        ax.legend(loc="upper right", fontsize=7, ncol=3)


def plot_reactions(r, time, stem, out):
    sources = load_sources(r)
    if not sources:
        return None
    scale = max(largest(force) for _, force, _ in sources)
    carries = [largest(force) > NOTHING * scale or (force is None and largest(moment) > 0.0)
               for _, force, moment in sources]
    kept = [source for source, load in zip(sources, carries) if load]
    idle = [source[0] for source, load in zip(sources, carries) if not load]
    if not kept:
        return None
    fig, axes = plt.subplots(len(kept), 2, sharex=True, figsize=(12, 2.5 * len(kept) + 0.9), squeeze=False)
    for row, (title, force, moment) in enumerate(kept):
        for col, (channel, components) in enumerate(((force, ("Fx", "Fy", "Fz")), (moment, ("Mx", "My", "Mz")))):
            ax = axes[row, col]
            # A moment below 1e-6 of the largest force times 1 m is round-off (a revolute
            # joint's moment about its free axis): said, not drawn.
            if channel is None or largest(channel) <= (NOTHING * scale if col == 1 else 0.0):
                ax.set_axis_off()
                if channel is not None:
                    ax.text(0.5, 0.5, f"{title}: no {'force' if col == 0 else 'moment'} (round-off)",
                            ha="center", va="center", fontsize=8, transform=ax.transAxes)
                continue
            draw_load(ax, time, channel, components)
            ax.set_title(f"{title}: {'force' if col == 0 else 'moment'}", fontsize=9, loc="left")
    caption = f"{stem}: loads of parent on child (world axes; moments about the joint origin)"
    if idle:
        caption += "\ncarry nothing (< 1e-6 of the largest load), not drawn: " + ", ".join(idle)
    fig.suptitle(caption, fontsize=10)
    for ax in axes[-1]:
        ax.set_xlabel("time [s]")
    return save(fig, out, stem, "reactions")


# --- energy -----------------------------------------------------------------------------

def plot_energy(r, time, stem, out):
    if "signals/total_energy" not in r:
        return None
    kinetic, potential, total = (r[f"signals/{name}"] for name in ("kinetic_energy", "potential_energy", "total_energy"))
    paths = [channel.lstrip("/") for channel in r.channels]
    working = sorted({path.split("/")[1] for path in paths if path.startswith(("forces/", "drivers/"))})
    if working:
        # Nothing records the work of the force elements: K + P changes by it, and that
        # change is the loads' doing, not the integrator's.
        fig, ax_e = plt.subplots(1, 1, figsize=(9, 4))
        ax_e.plot(time, kinetic - kinetic[0], label="kinetic T − T0")
        ax_e.plot(time, potential - potential[0], label="potential V − V0")
        ax_e.plot(time, total - total[0], "k", label="T + V − (T0 + V0)")
        ax_e.set_ylabel("energy change [J]")
        ax_e.set_title(f"{stem}: mechanical energy; it changes by the work of {', '.join(working)}\n"
                       "(not a check of the integration: that is only where nothing else does work)", fontsize=9)
        ax_e.set_xlabel("time [s]")
        ax_e.grid(True, alpha=0.3)
        ax_e.legend(loc="upper right", fontsize=8)
        return save(fig, out, stem, "energy")
    fig, (ax_e, ax_d) = plt.subplots(2, 1, sharex=True, figsize=(9, 6))
    ax_e.plot(time, kinetic, label="kinetic")
    ax_e.plot(time, potential, label="potential")
    ax_e.plot(time, total, "k", label="total")
    ax_e.set_ylabel("energy [J]")
    ax_e.set_title(f"{stem}: energy (only gravity and joint springs do work: the total is conserved)")
    scale = max(abs(total[0]), np.max(kinetic), 1e-300)
    ax_d.plot(time, (total - total[0]) / scale)
    ax_d.set_ylabel("drift (E − E0) / max(|E0|, max T) [-]")
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
