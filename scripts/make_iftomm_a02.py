#!/usr/bin/env python3
"""Writes the case of IFToMM benchmark A02, the N-four-bar mechanism, for any N.

    scripts/make_iftomm_a02.py N [--t-end SECONDS] [--check ID] [-o FILE]

N windows: N + 1 vertical cranks of 1 m and 1 kg pivoted 1 m apart on ground, N
coupler bars of 1 m and 1 kg joining their tips, closed by revolute loop joints
(González et al., "A benchmarking system for MBS simulation software", Multibody
System Dynamics 16 (2006); iftomm-multibody.org, problem A02; docs/physics/benchmarks.md).
The defaults (10 s, check L2) reproduce cases/validation/iftomm_a02_n1.yaml and
iftomm_a02_n2.yaml; the benchmark's own size is N = 40 over 20 s:

    scripts/make_iftomm_a02.py 40 --t-end 20 --check A02 -o cases/validation/iftomm_a02_n40.yaml
"""
import argparse
import sys


def number(value):
    """10.0 -> '10', 0.5 -> '0.5' (the way the hand-written cases spell times)."""
    return f"{value:g}"


def case_text(windows, t_end, check):
    cranks = windows + 1
    lines = [
        f"name: iftomm_a02_n{windows}",
        "description: >",
        f"  Validation {check}: IFToMM benchmark A02, the N-four-bar mechanism with N = {windows}: {cranks} vertical",
        f"  cranks of 1 m and 1 kg pivoted 1 m apart on ground, {windows} coupler bars of 1 m and 1 kg",
        "  joining their tips (closed by revolute loop joints), gravity 9.81 m/s^2 along -y.",
        "  Start vertical, B0 (the first crank tip) moving at 1 m/s. The cranks lie flat on the",
        "  ground line at q = pi/2 + k pi: every such pass is a singular (bifurcation)",
        "  configuration where the parallelogram could switch branch.",
        "environment:",
        "  gravity: [0, -9.81, 0]",
        "bodies:",
    ]
    for crank in range(cranks):
        lines += [
            f"  - name: crank{crank}       # frame on the pivot, the rod along +y",
            "    mass: 1",
            "    center_of_mass: [0, 0.5, 0]",
            "    inertia: {ixx: 1/12, iyy: 0, izz: 1/12}",
        ]
    for coupler in range(windows):
        lines += [
            f"  - name: coupler{coupler}     # frame on crank{coupler}'s tip, the rod along +x",
            "    mass: 1",
            "    center_of_mass: [0.5, 0, 0]",
            "    inertia: {ixx: 0, iyy: 1/12, izz: 1/12}",
        ]
    lines.append("joints:")
    for crank in range(cranks):
        lines += [
            f"  - name: pivot{crank}",
            "    type: revolute",
            "    parent: ground",
            f"    child: crank{crank}",
            "    axis: [0, 0, 1]",
            f"    parent_frame: {{position: [{crank}, 0, 0]}}",
            "    initial: {q: 0, qd: 1}",
        ]
    for coupler in range(windows):
        lines += [
            f"  - name: tip{coupler}",
            "    type: revolute",
            f"    parent: crank{coupler}",
            f"    child: coupler{coupler}",
            "    axis: [0, 0, 1]",
            "    parent_frame: {position: [0, 1, 0]}",
            "    initial: {q: 0, qd: -1}   # the coupler translates: its angle stays 0",
        ]
    lines.append("loop_joints:")
    for coupler in range(windows):
        lines += [
            f"  - name: closure{coupler}",
            "    type: revolute",
            f"    parent: coupler{coupler}",
            f"    child: crank{coupler + 1}",
            "    axis: [0, 0, 1]",
            "    parent_frame: {position: [1, 0, 0]}",
            "    child_frame: {position: [0, 1, 0]}",
        ]
    lines += [
        "solver:",
        "  # The index-3 HHT integrator (trapezoidal rule, augmented Lagrangian, projections)",
        "  # passes every singular configuration; IDA's index-2 form and the explicit methods'",
        f"  # index-1 form lose rank there (docs/validation.md, {check}).",
        "  integrator: hht",
        "  step: 2e-4",
        "  rtol: 1e-10",
        "  atol: 1e-10",
        f"  t_end: {number(t_end)}",
        "output:",
        "  interval: 0.01",
    ]
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("windows", type=int, help="N, the number of four-bar windows (>= 1)")
    parser.add_argument("--t-end", type=float, default=10.0, help="end time [s] (benchmark: 20)")
    parser.add_argument("--check", default="L2", help="validation check id named in the description")
    parser.add_argument("-o", "--output", help="file to write (default: standard output)")
    arguments = parser.parse_args()
    if arguments.windows < 1:
        parser.error("N must be at least 1")
    if arguments.t_end <= 0:
        parser.error("--t-end must be positive")
    text = case_text(arguments.windows, arguments.t_end, arguments.check)
    if arguments.output:
        with open(arguments.output, "w", encoding="utf-8") as file:
            file.write(text)
    else:
        sys.stdout.write(text)


if __name__ == "__main__":
    main()
