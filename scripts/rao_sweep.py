#!/usr/bin/python3
"""Heave RAO of the MSS semi by time-domain sweep, over the frequency-domain RAO.

Runs cases/hydro/regular_wave.yaml once per wave period (--set parameters.period=T,
--set parameters.amplitude=a), fits x(t) = c + Re[X e^{i w t}] by least squares to the
heave after the ramp (the last --cycles periods), and plots |X|/a and arg X against the
frequency-domain RAO computed here from the WAMIT files directly:

    X3/a = X3_bar rho g / (C33 - w^2 (m + A33(w)) + i w (B33(w) + b_visc))

with A33, B33 from semisub.1, X3 from semisub.3 (all linear in w between the BEM points) at the case's heading (180 deg), C33
from semisub.hst, m from semisub.frc and b_visc the case's linear heave damping.
Usage: scripts/rao_sweep.py [--periods 6 8 10 ...] [-o results/rao]
"""
import argparse
import os
import pathlib
import subprocess
import sys

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent))
import heavesim  # noqa: E402  the repository's heavesim.py: the package in build/python

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DATA = os.path.join(ROOT, "data", "mss_semisub")
RHO, G, B_VISC, MASS = 1025.0, 9.81, 3.3e6, 51979800.0


def rows(path):
    out = []
    with open(path) as f:
        for line in f:
            try:
                out.append([float(w) for w in line.split()])
            except ValueError:
                pass
    return out


def frequency_domain_rao(periods, heading_deg=180.0):
    """Complex heave RAO [m/m] per period, from the WAMIT files (ULEN = 1)."""
    c33 = next(RHO * G * r[2] for r in rows(os.path.join(DATA, "semisub.hst")) if len(r) == 3 and r[:2] == [3, 3])
    radiation = sorted((r[0], r[3], r[4]) for r in rows(os.path.join(DATA, "semisub.1"))
                       if len(r) == 5 and r[1] == 3 and r[2] == 3 and r[0] > 0)
    excitation = sorted((r[0], r[5], r[6]) for r in rows(os.path.join(DATA, "semisub.3"))
                        if len(r) == 7 and r[2] == 3 and abs(r[1] - heading_deg) < 1e-6)
    # Linear in w (as hydro/ interpolates X and B), on Re and Im of X separately.
    w_r = 2 * np.pi / np.array([r[0] for r in radiation])[::-1]
    w_x = 2 * np.pi / np.array([x[0] for x in excitation])[::-1]
    result = []
    for T in periods:
        w = 2 * np.pi / T
        a33 = RHO * np.interp(w, w_r, [r[1] for r in radiation][::-1])
        b33 = RHO * w * np.interp(w, w_r, [r[2] for r in radiation][::-1])
        x3 = RHO * G * (np.interp(w, w_x, [x[1] for x in excitation][::-1]) +
                        1j * np.interp(w, w_x, [x[2] for x in excitation][::-1]))
        result.append(x3 / (c33 - w * w * (MASS + a33) + 1j * w * (b33 + B_VISC)))
    return np.array(result)


def fit_heave(path, period, cycles):
    with heavesim.open(path) as r:
        t = r.time
        x = np.asarray(r["joints/heave/q"]).reshape(len(t))
    keep = t >= t[-1] - cycles * period
    w = 2 * np.pi / period
    basis = np.column_stack([np.cos(w * t[keep]), np.sin(w * t[keep]), np.ones(keep.sum())])
    c, *_ = np.linalg.lstsq(basis, x[keep], rcond=None)
    return complex(c[0], -c[1])  # x = Re[X e^{iwt}] = Xr cos - Xi sin


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--periods", type=float, nargs="+", default=[6, 8, 10, 12, 14, 16, 18, 20, 22, 25])
    parser.add_argument("--amplitude", type=float, default=1.0, help="wave amplitude a [m]")
    parser.add_argument("--cycles", type=int, default=5, help="periods fitted at the end of each run")
    parser.add_argument("--t-end", type=float, default=600.0, help="run length [s] (ramp 30 s)")
    parser.add_argument("--binary", default=os.path.join(ROOT, "build", "heavesim"))
    parser.add_argument("-o", "--output", default="results/rao")
    args = parser.parse_args()
    os.makedirs(args.output, exist_ok=True)
    case = os.path.join(ROOT, "cases", "hydro", "regular_wave.yaml")
    measured = []
    for T in args.periods:
        out = os.path.join(args.output, f"regular_T{T:g}.h5")
        subprocess.run([args.binary, "run", case, "-o", out, "--set", f"parameters.period={T}",
                        "--set", f"parameters.amplitude={args.amplitude}", "--set", f"solver.t_end={args.t_end}",
                        "--set", "output.interval=0.1", "--set", f"output.evaluate_after={args.t_end / 2}"],
                       check=True, stdout=subprocess.DEVNULL)
        measured.append(fit_heave(out, T, args.cycles) / args.amplitude)
    measured = np.array(measured)
    reference = frequency_domain_rao(args.periods)
    print("T [s]   |X3|/a time domain   frequency domain   ratio   phase difference [deg]")
    for T, m, r in zip(args.periods, measured, reference):
        print(f"{T:5.1f}   {abs(m):18.4f}   {abs(r):16.4f}   {abs(m) / abs(r):5.3f}   "
              f"{np.degrees(np.angle(m / r)):8.2f}")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    dense = np.linspace(min(args.periods), max(args.periods), 300)
    fd = frequency_domain_rao(dense)
    w_dense, w = 2 * np.pi / dense, 2 * np.pi / np.array(args.periods)
    fig, (ax1, ax2) = plt.subplots(2, 1, sharex=True, figsize=(7, 6))
    ax1.plot(w_dense, abs(fd), label="frequency domain (WAMIT, linear interp.)")
    ax1.plot(w, abs(measured), "o", label="heavesim, fit after the ramp")
    ax1.set_ylabel("|heave| / a [m/m]")
    ax1.legend()
    ax2.plot(w_dense, np.degrees(np.angle(fd)))
    ax2.plot(w, np.degrees(np.angle(measured)), "o")
    ax2.set_ylabel("phase [deg]")
    ax2.set_xlabel("w [rad/s]")
    fig.suptitle("MSS semi heave RAO, head seas")
    fig.savefig(os.path.join(args.output, "heave_rao.png"), dpi=120)
    print("wrote", os.path.join(args.output, "heave_rao.png"))


if __name__ == "__main__":
    main()
