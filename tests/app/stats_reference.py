#!/usr/bin/python3
"""Independent reference for `heavesim stats` (tests/app/test_stats_command.cpp).

    stats_reference.py RESULT.h5 CHANNEL STATS.json DURATION

Recomputes the statistics of column 0 of CHANNEL with numpy and scipy from the file's
samples (the window starting at the root attribute statistics_window_start), straight from the
definitions of docs/physics/statistics.md, and compares them with heavesim's JSON.
Prints each comparison; exits 1 if any differs beyond its tolerance.
"""
import json
import math
import sys

import h5py
import numpy as np
from scipy import signal, stats

path, channel, json_path, duration = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4])
with h5py.File(path, "r") as f:
    n = int(f.attrs["samples_written"])
    t = f["time"][:n]
    x = np.asarray(f[channel][:n], dtype=float).reshape(n, -1)[:, 0]
    start = float(f.attrs["statistics_window_start"])
with open(json_path) as handle:
    mine = json.load(handle)["channels"][0]["statistics"]

x = x[t >= start - 1e-9]
dt = (t[-1] - t[0]) / (n - 1)
mean, std = x.mean(), x.std(ddof=1)
up = np.nonzero((x[:-1] < mean) & (x[1:] >= mean))[0]  # x_i < m <= x_(i+1)
crests = np.array([x[a + 1:b + 1].max() for a, b in zip(up[:-1], up[1:])])
tz = (len(x) - 1) * dt / len(up)
highest_third = np.sort(crests)[::-1][: len(crests) // 3]
n_duration = duration / tz
excursions = crests - mean
k, _, scale = stats.weibull_min.fit(excursions, floc=0)
segment = 4
while segment * 2 <= 4096 and segment * 2 * 4 <= len(x):
    segment *= 2
f_welch, density = signal.welch(x, fs=1 / dt, nperseg=segment)  # hann, half overlap, constant detrend
df = f_welch[1] - f_welch[0]
m0, m2, m4 = (np.sum(f_welch**p * density) * df for p in (0, 2, 4))

expected = {
    "window_samples": (len(x), 0),
    "window_mean": (mean, 1e-12 * abs(mean) + 1e-12 * std),
    "window_standard_deviation": (std, 1e-10 * std),
    "skewness": (stats.skew(x), 1e-8),
    "kurtosis": (stats.kurtosis(x, fisher=False), 1e-8),
    "upcrossings": (len(up), 0),
    "zero_upcrossing_period": (tz, 1e-10 * tz),
    "cycles": (len(crests), 0),
    "significant_crest": (highest_third.mean(), 1e-10 * std),
    "mpm_rayleigh_duration": (mean + std * math.sqrt(2 * math.log(n_duration)), 1e-9 * std),
    # scipy's optimiser stops at its own tolerance: 1e-4 relative
    "weibull_shape": (k, 1e-4 * k),
    "weibull_scale": (scale, 1e-4 * scale),
    "spectral_m0": (m0, 1e-9 * m0),
    "spectral_m2": (m2, 1e-9 * m2),
    "spectral_m4": (m4, 1e-9 * m4),
    "spectral_peak_period": (1 / f_welch[1 + np.argmax(density[1:])], 1e-12),
}
failed = False
for name, (value, tolerance) in expected.items():
    got = mine[name]
    ok = got is not None and abs(got - value) <= tolerance
    failed |= not ok
    print(f"{'ok  ' if ok else 'FAIL'} {name}: heavesim {got!r} numpy {value!r} (tolerance {tolerance:.3g})")
sys.exit(1 if failed else 0)
