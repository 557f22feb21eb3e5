#!/usr/bin/python3
"""Writes an Hs-Tp scatter diagram discretised from a published joint model of the sea
states: the North Atlantic model of DNV-RP-C205 (2010) section 3.6.

The model (DNV-RP-C205 section 3.6, after Bitner-Gregersen and Haver): Hs follows a
three-parameter Weibull distribution

    F(h) = 1 - exp(-((h - gamma) / alpha)^beta),      alpha = 3.041 m, beta = 1.484, gamma = 0.661 m

and the zero-crossing period given Hs a log-normal one, ln Tz ~ N(mu(h), sigma(h)^2),

    mu(h) = a0 + a1 h^a2,             a0 = 0.70,   a1 = 1.27,   a2 = 0.131
    sigma(h) = b0 + b1 exp(b2 h),     b0 = 0.1334, b1 = 0.0264, b2 = -0.1906

(h in metres, Tz in seconds). The sweeps run JONSWAP seas given by Tp, so each Tp class
[lo, hi) is the Tz class [k lo, k hi) with k = Tz/Tp of the JONSWAP spectrum of
peakedness gamma_J (DNV-RP-C205 section 3.5.5: Tz/Tp = 0.6673 + 0.05037 g - 0.006230 g^2
+ 0.0003341 g^3; 0.7776 at g = 3.3). The probability of cell (i, j) is

    P_ij = integral over the Hs class i of f(h) [Phi(z_hi(h)) - Phi(z_lo(h))] dh,
    z(h) = (ln(k T) - mu(h)) / sigma(h),

by adaptive quadrature (scipy.integrate.quad). The first and last class of each
variable also take the tails (Hs and Tp below the first edge and above the last), so
the table holds all of the probability; the occurrences are written per 100,000 sea
states, as the Global Wave Statistics tables are.

The output is the scatter-diagram text form `heavesim sweep` reads: '#' comment lines,
a first row of the Tp class centres [s], then one row per Hs
class: its centre [m] and the occurrence in each Tp class.

    /usr/bin/python3 scripts/scatter_diagram.py -o data/scatter/north_atlantic_dnv_rp_c205.txt
"""
import argparse
import math
import sys

import numpy as np
from scipy import integrate, stats

# DNV-RP-C205 (2010) section 3.6, North Atlantic.
WEIBULL = {"alpha": 3.041, "beta": 1.484, "gamma": 0.661}
LOG_MEAN = {"a0": 0.70, "a1": 1.27, "a2": 0.131}
LOG_STD = {"b0": 0.1334, "b1": 0.0264, "b2": -0.1906}


def tz_over_tp(peakedness):
    """Tz/Tp of a JONSWAP spectrum (the fit of DNV-RP-C205 section 3.5.5)."""
    g = peakedness
    return 0.6673 + 0.05037 * g - 0.006230 * g**2 + 0.0003341 * g**3


def hs_density(h):
    w = WEIBULL
    return stats.weibull_min.pdf(h, w["beta"], loc=w["gamma"], scale=w["alpha"])


def hs_distribution(h):
    w = WEIBULL
    return stats.weibull_min.cdf(h, w["beta"], loc=w["gamma"], scale=w["alpha"])


def tz_distribution_given_hs(tz, h):
    """P(Tz <= tz | Hs = h) of the conditional log-normal."""
    mu = LOG_MEAN["a0"] + LOG_MEAN["a1"] * h ** LOG_MEAN["a2"]
    sigma = LOG_STD["b0"] + LOG_STD["b1"] * math.exp(LOG_STD["b2"] * h)
    if tz <= 0.0:
        return 0.0
    if math.isinf(tz):
        return 1.0
    return stats.norm.cdf((math.log(tz) - mu) / sigma)


def edges_of(centres):
    """Class edges halfway between centres; the outer edges open (the tails join the end classes)."""
    inner = [(a + b) / 2 for a, b in zip(centres[:-1], centres[1:])]
    return [-math.inf] + inner + [math.inf]


def table(hs_centres, tp_centres, peakedness):
    k = tz_over_tp(peakedness)
    hs_edges, tp_edges = edges_of(hs_centres), edges_of(tp_centres)
    probability = np.zeros((len(hs_centres), len(tp_centres)))
    for i in range(len(hs_centres)):
        lower = max(hs_edges[i], WEIBULL["gamma"])
        upper = hs_edges[i + 1]
        if upper <= lower:
            continue
        for j in range(len(tp_centres)):
            def cell_density(h):
                return hs_density(h) * (tz_distribution_given_hs(k * tp_edges[j + 1], h) -
                                        tz_distribution_given_hs(k * tp_edges[j], h))
            value, _ = integrate.quad(cell_density, lower, upper, limit=200, epsabs=1e-12, epsrel=1e-10)
            probability[i, j] = value
    return probability


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--hs", type=float, nargs="+", default=[1, 3, 5, 7, 9, 11], help="Hs class centres [m]")
    parser.add_argument("--tp", type=float, nargs="+", default=[6, 8, 10, 12, 14, 16], help="Tp class centres [s]")
    parser.add_argument("--peakedness", type=float, default=3.3, help="JONSWAP gamma of the swept seas")
    parser.add_argument("-o", "--output", default="-", help="output file (default stdout)")
    arguments = parser.parse_args()

    probability = table(arguments.hs, arguments.tp, arguments.peakedness)
    total = probability.sum()
    if abs(total - 1.0) > 1e-6:  # the classes cover (gamma, inf) x (0, inf): all of it
        sys.exit(f"scatter_diagram: the cells hold {total} of the probability, expected 1")
    occurrence = probability * 1e5
    lines = [
        "# Hs-Tp scatter diagram, North Atlantic: the joint model of DNV-RP-C205 (2010) section 3.6",
        "# (Hs three-parameter Weibull alpha = 3.041 m, beta = 1.484, gamma = 0.661 m; ln Tz | Hs normal with",
        "# mu = 0.70 + 1.27 Hs^0.131, sigma = 0.1334 + 0.0264 exp(-0.1906 Hs)), discretised by",
        f"# scripts/scatter_diagram.py with Tz = {tz_over_tp(arguments.peakedness):.4f} Tp (JONSWAP gamma = "
        f"{arguments.peakedness:g}, DNV-RP-C205 section 3.5.5).",
        "# Classes: edges halfway between centres; the first and last class of each variable take the tails.",
        "# Occurrences per 100,000 sea states. First row: Tp class centres [s]; first column: Hs class centres [m].",
        " ".join(f"{t:g}" for t in arguments.tp),
    ]
    for hs, row in zip(arguments.hs, occurrence):
        lines.append(f"{hs:g} " + " ".join(f"{value:.1f}" for value in row))
    text = "\n".join(lines) + "\n"
    if arguments.output == "-":
        sys.stdout.write(text)
    else:
        with open(arguments.output, "w") as f:
            f.write(text)


if __name__ == "__main__":
    main()
