#!/usr/bin/python3
"""Where the integrating (main) thread of `heavesim run` spends its time: integration,
set-up, or recording (the result file's layout, the samples, the statistics, the end).

    /usr/bin/python3 scripts/recording_share.py [--binary build/heavesim] [--runs 6] CASE.yaml [--set k=v ...]

Runs the case `--runs` times under `perf record --call-graph dwarf` (Debian's linux-perf)
and classifies every sample of the main thread by the frames on its stack:
integration (Integrator::advance_to, initialize, make_integrator), set-up (load_case or
resolved_case_tree and read_case, build_scene) and everything else run_command does, which is recording. The share is of
CPU samples, so it does not depend on the machine's speed between runs, but it counts
only the main thread (the helper threads, reported beside it, run on the other core); the
wall-time proxy of docs/performance.md (a run with 7 samples against the full one)
leaves out the recording's fixed cost, which the 7-sample run pays too.
"""
import argparse
import collections
import os
import shutil
import subprocess
import sys
import tempfile

# The functions of the set-up: reading the case (load_case, or resolved_case_tree and then
# read_case, as `run` does) and building its scene. scripts/instruction_share.py counts the same.
SET_UP_FUNCTIONS = ("load_case", "resolved_case_tree", "read_case", "build_scene")
PARTS = [
    ("integration", ("Integrator::advance_to", "Integrator::initialize", "make_integrator")),
    ("set-up", SET_UP_FUNCTIONS),
]
# Named pieces of the recording, reported beside the three shares (a stack may hold several).
DETAILS = [
    ("recorder constructor (channels)", "Recorder::Recorder"),
    ("the result file's layout (Recorder::create_layout: datasets, attributes, first flush)",
     "Recorder::create_layout"),
    ("per-sample evaluation (MultibodySystem::evaluate)", "MultibodySystem::evaluate"),
    ("per-sample channels (Recorder::fill_row)", "Recorder::fill_row"),
    ("per-sample record in order (Recorder::commit_row)", "Recorder::commit_row"),
    ("end of run (Recorder::finish)", "Recorder::finish"),
]
# The helper threads, by the job on their stacks (app/output/background_worker.hpp).
# The compiler inlines the jobs themselves (record_batch, write_last_blocks) into the
# worker's lambda: what they call names them.
HELPERS = [
    ("the result file's layout (Recorder::create_layout), the samples' thread's first job",
     ("Recorder::create_layout",)),
    ("samples' evaluation (MultibodySystem::evaluate, Recorder::fill_row, Recorder::commit_row)",
     ("MultibodySystem::evaluate", "Recorder::fill_row", "Recorder::commit_row", "Recorder::record_batch")),
    ("block statistics (Recorder::add_block_statistics)", ("Recorder::add_block_statistics",)),
    ("block writes (ResultFile::write_rows)", ("ResultFile::write_rows", "ResultFile::write_last_blocks")),
]


def stacks(perf_script_text):
    """Yields (thread name, frames) per sample of `perf script -F comm,tid,ip,sym` output."""
    frames, header = [], None
    for line in perf_script_text.splitlines():
        if not line.strip():
            if header is not None:
                yield header, frames
            frames, header = [], None
        elif not line[0].isspace():
            header = line.strip()
        else:
            parts = line.strip().split(None, 1)
            frames.append(parts[1] if len(parts) > 1 else "?")
    if header is not None:
        yield header, frames


def case_parser(description):
    """The command line both share scripts take: CASE.yaml, --binary, --set k=v ..."""
    parser = argparse.ArgumentParser(description=description, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("case")
    parser.add_argument("--binary", default="build/heavesim")
    parser.add_argument("--set", action="append", default=[], dest="overrides")
    return parser


def run_line(arguments, result):
    """The `heavesim run` command line of the case, writing `result`."""
    run = [arguments.binary, "run", arguments.case, "-o", result, "-q"]
    for override in arguments.overrides:
        run += ["--set", override]
    return run


def print_shares(shares, total):
    """One line per (name, count): its percentage of `total`."""
    for name, count in shares:
        print(f"  {100.0 * count / total:5.1f} %  {name}")


def main():
    parser = case_parser(__doc__)
    parser.add_argument("--runs", type=int, default=6)
    arguments = parser.parse_args()
    if shutil.which("perf") is None:
        sys.exit("recording_share: needs perf (apt-get install linux-perf)")
    with tempfile.TemporaryDirectory() as directory:
        data, result = os.path.join(directory, "perf.data"), os.path.join(directory, "run.h5")
        loop = " && ".join([" ".join(run_line(arguments, result))] * arguments.runs)
        subprocess.run(["perf", "record", "-q", "-F", "10000", "--call-graph", "dwarf,16384", "-o", data, "--",
                        "sh", "-c", loop], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        text = subprocess.run(["perf", "script", "-i", data, "-F", "comm,tid,ip,sym"], check=True,
                              capture_output=True, text=True).stdout
    shares, details, helpers, total = collections.Counter(), collections.Counter(), collections.Counter(), 0
    for _, frames in stacks(text):
        if not any("heavesim::run_command" in frame for frame in frames):
            # A helper thread's (counted beside), or a stack perf could not unwind.
            name = next((name for name, keys in HELPERS if any(k in frame for frame in frames for k in keys)), None)
            if name:
                helpers[name] += 1
            continue
        total += 1
        part = next((name for name, keys in PARTS if any(k in f for f in frames for k in keys)), "recording")
        shares[part] += 1
        for name, key in DETAILS:
            if any(key in frame for frame in frames):
                details[name] += 1
    if total == 0:
        sys.exit("recording_share: no sample of the main thread was unwound")
    print(f"{total} samples of the main thread over {arguments.runs} runs of {arguments.case}")
    print_shares([(name, shares[name]) for name in ("recording", "integration", "set-up")], total)
    print("  of which, in the recording:")
    print_shares([(name, details[name]) for name, _ in DETAILS], total)
    print("  beside the main thread, CPU on the helper threads, in % of the main thread's:")
    print_shares([(name, helpers[name]) for name, _ in HELPERS], total)


if __name__ == "__main__":
    main()
