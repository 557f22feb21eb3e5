#!/usr/bin/python3
"""Compares two builds of a Google Benchmark binary, alternating them on a noisy machine.

    scripts/bench_compare.py BEFORE_BINARY AFTER_BINARY [--rounds 5] [--filter REGEX]

Runs BEFORE, AFTER, BEFORE, AFTER, ... (`--rounds` of each), each run with
--benchmark_format=json, takes each benchmark's smallest real time over the rounds (the
least disturbed run), and prints after / before per benchmark and their geometric mean.
A ratio below 1 means the after build is faster. Used for docs/performance.md's
before/after tables.
"""
import argparse
import json
import math
import subprocess
import sys


def run(binary, benchmark_filter):
    command = [binary, "--benchmark_format=json"]
    if benchmark_filter:
        command.append(f"--benchmark_filter={benchmark_filter}")
    output = subprocess.run(command, check=True, capture_output=True, text=True).stdout
    return {b["name"]: b["real_time"] for b in json.loads(output)["benchmarks"] if b.get("run_type") != "aggregate"}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("before")
    parser.add_argument("after")
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--filter", default="")
    arguments = parser.parse_args()
    best = {"before": {}, "after": {}}
    for _ in range(arguments.rounds):
        for label in ("before", "after"):
            for name, time in run(getattr(arguments, label), arguments.filter).items():
                best[label][name] = min(time, best[label].get(name, math.inf))
    names = [n for n in best["before"] if n in best["after"]]
    if not names:
        print("no benchmark in common", file=sys.stderr)
        return 1
    width = max(len(n) for n in names)
    print(f"{'benchmark':{width}s}  {'before':>12s}  {'after':>12s}  after/before")
    logs = []
    for name in names:
        ratio = best["after"][name] / best["before"][name]
        logs.append(math.log(ratio))
        print(f"{name:{width}s}  {best['before'][name]:12.1f}  {best['after'][name]:12.1f}  {ratio:8.3f}")
    print(f"geometric mean of after/before over {len(names)} benchmarks: {math.exp(sum(logs) / len(logs)):.3f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
