#!/usr/bin/env python3
"""Mutation test of the input contract: `heavesim check` on mutated copies of cases.

For every numeric value of each case (after its `include:` files are merged, so that
a value from an included file is reached too), the value is replaced through
`--set key.path=value` by each mutation (x1e200, x1e-9, 0, -1, 1e308, nan, inf, 1e14,
1e-300) and the exit code of `heavesim check` is recorded. Exit 0 (accepted) and 2 (bad input
naming a key) are the contract; 3 at check time, 1, a signal or a hang (timeout) are
failures of it and are listed.

usage: scripts/mutate_cases.py [--binary build/heavesim] [--timeout 20] [cases ...]
       (default cases: cases/*.yaml cases/hydro/*.yaml)
"""
import argparse
import collections
import concurrent.futures
import glob
import os
import subprocess
import sys

import yaml

# The mutations, plus values just inside the finite range (1e14) and tiny
# positive ones (1e-300), which pass "> 0" rules and may overflow what divides by them.
MUTATIONS = [("x1e200", lambda v: f"({v})*1e200"), ("x1e-9", lambda v: f"({v})*1e-9"), ("0", lambda v: "0"),
             ("-1", lambda v: "-1"), ("1e308", lambda v: "1e308"), ("nan", lambda v: "nan"),
             ("inf", lambda v: "inf"), ("1e14", lambda v: "1e14"), ("1e-300", lambda v: "1e-300")]


def is_named_list(node):
    return isinstance(node, list) and node and all(
        isinstance(i, dict) and "name" in i and not isinstance(i["name"], (dict, list)) for i in node)


def merge_into(base, overlay):
    """The merge rule of app/case/case_merge.hpp: maps by key, named lists by name."""
    if isinstance(base, dict) and isinstance(overlay, dict):
        for key, value in overlay.items():
            base[key] = merge_into(base[key], value) if key in base else value
        return base
    if is_named_list(base) and is_named_list(overlay):
        for item in overlay:
            match = next((b for b in base if b["name"] == item["name"]), None)
            if match is None:
                base.append(item)
            else:
                merge_into(match, item)
        return base
    return overlay


def load_resolved(path):
    with open(path) as f:
        document = yaml.safe_load(f) or {}
    includes = document.pop("include", [])
    includes = [includes] if isinstance(includes, str) else includes
    merged = {}
    for name in includes:
        merge_into(merged, load_resolved(os.path.join(os.path.dirname(path), name)))
    return merge_into(merged, document)


def is_number(value):
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def numeric_leaves(node, path=""):
    """(key path in --set spelling, value) for every number of the case."""
    if isinstance(node, dict):
        for key, value in node.items():
            if key in ("name", "description", "seed"):
                continue
            yield from numeric_leaves(value, f"{path}.{key}" if path else str(key))
    elif isinstance(node, list):
        named = is_named_list(node)
        for index, item in enumerate(node):
            yield from numeric_leaves(item, f"{path}[{item['name'] if named else index}]")
    elif is_number(node):
        yield path, node


def check(binary, case, assignment, timeout):
    try:
        result = subprocess.run([binary, "check", case, "--set", assignment], capture_output=True, text=True,
                                timeout=timeout)
        return result.returncode, (result.stderr + result.stdout).strip().splitlines()[-1:] or [""]
    except subprocess.TimeoutExpired:
        return "timeout", [f"no answer in {timeout} s"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--binary", default="build/heavesim")
    parser.add_argument("--timeout", type=float, default=20.0)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("cases", nargs="*")
    options = parser.parse_args()
    cases = options.cases or sorted(glob.glob("cases/*.yaml") + glob.glob("cases/hydro/*.yaml"))

    jobs = []
    for case in cases:
        for path, value in numeric_leaves(load_resolved(case)):
            for label, mutate in MUTATIONS:
                jobs.append((case, path, label, f"{path}={mutate(value)}"))

    counts = collections.Counter()
    failures = []
    with concurrent.futures.ThreadPoolExecutor(options.jobs) as pool:
        results = pool.map(lambda job: check(options.binary, job[0], job[3], options.timeout), jobs)
        for (case, path, label, assignment), (code, last_line) in zip(jobs, results):
            counts[code] += 1
            if code not in (0, 2):
                failures.append(f"{case} --set '{assignment}': exit {code}: {last_line[0]}")
    for failure in failures:
        print(failure)
    print(f"{len(cases)} cases, {len(jobs)} mutated checks: " +
          ", ".join(f"exit {code}: {n}" for code, n in sorted(counts.items(), key=lambda kv: str(kv[0]))))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
