#!/usr/bin/python3
"""Where the instructions of one `heavesim run` go: integration, set-up, the process's
start, and the rest, which is recording (the result file's layout, the samples' evaluation,
their channels and statistics, the writes, the end of the run).

    /usr/bin/python3 scripts/instruction_share.py [--binary build/heavesim] CASE.yaml [--set k=v ...]

Runs the case once under Valgrind's callgrind (Debian's valgrind; ~50 times slower than a
plain run) and reads the inclusive instruction counts of named functions on every thread.
Unlike the CPU samples of scripts/recording_share.py, an instruction count does not depend
on what else the shared machine runs, so two binaries compare in one call each; it does not
see cache misses, page faults or time in the kernel (the writes' copies into the page
cache), which the wall-time ratios of docs/performance.md do. The same split is printed
for the integrating thread alone, without the helper threads that run beside it.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from recording_share import SET_UP_FUNCTIONS, case_parser, print_shares, run_line  # noqa: E402

# (part, function names whose inclusive counts add up to it). The integrator's residuals
# evaluate the system inside advance_to, so they count as integration, as they should.
PARTS = [  # names that do not nest in a run (load_case is resolved_case_tree + read_case, which `run` calls itself)
    ("integration", ("IdaIntegrator::advance_to", "IdaIntegrator::initialize", "ErkIntegrator::advance_to",
                     "Rk4Integrator::advance_to", "HhtIntegrator::advance_to", "make_integrator")),
    ("set-up", tuple("heavesim::" + name for name in SET_UP_FUNCTIONS)),
]
DETAILS = [
    ("recorder constructor (channels)", ("Recorder::Recorder",)),
    ("the result file's layout (Recorder::create_layout: datasets, attributes, first flush; on the"
     " samples' thread when they are evaluated beside)", ("Recorder::create_layout",)),
    ("the helper threads (BackgroundWorker::loop: samples, statistics, writes)", ("BackgroundWorker::loop",)),
    ("the samples' channels and their record in order (Recorder::fill_row, Recorder::commit_row;"
     " their evaluation is beside it)", ("Recorder::fill_row", "Recorder::commit_row")),
    ("block statistics (Recorder::add_block_statistics, every thread)", ("Recorder::add_block_statistics",)),
    ("of which Welch spectra (WelchAccumulator::add)", ("WelchAccumulator::add",)),
    ("block writes (ResultFile::write_rows)", ("ResultFile::write_rows",)),
    ("end of run (Recorder::finish)", ("Recorder::finish",)),
]


def inclusive_counts(annotated):
    """{function: inclusive instructions} from `callgrind_annotate --inclusive=yes` text."""
    counts = {}
    for line in annotated.splitlines():
        match = re.match(r"\s*([\d,]+) \(\s*[\d.]+%\)\s+\S*?:(.*?)(?: \[.*\])?$", line)
        if match:
            name = match.group(2)
            counts[name] = max(counts.get(name, 0), int(match.group(1).replace(",", "")))
    return counts


def program_total(annotated):
    """All the instructions of a profile: its PROGRAM TOTALS line."""
    return int(re.search(r"([\d,]+) \(100.0%\)\s+PROGRAM TOTALS", annotated).group(1).replace(",", ""))


def total_of(counts, keys):
    """Sum over the functions whose name (before its parameter list) ends in one of `keys`
    (so `load_case` is not `load_case_tree`; a function
    that calls another of the same part would count twice: the names here do not nest)."""
    total = 0
    for key in keys:
        total += max((value for name, value in counts.items() if name.split("(")[0].endswith(key)), default=0)
    return total


def main():
    arguments = case_parser(__doc__).parse_args()
    if shutil.which("valgrind") is None:
        sys.exit("instruction_share: needs valgrind (apt-get install valgrind)")
    with tempfile.TemporaryDirectory() as directory:
        profile, result = os.path.join(directory, "callgrind.out"), os.path.join(directory, "run.h5")
        start = os.path.join(directory, "start.out")
        for command, output in ((run_line(arguments, result), profile), ([arguments.binary, "--version"], start)):
            subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={output}"] + command,
                           check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        annotated = [subprocess.run(["callgrind_annotate", "--inclusive=yes", "--threshold=100", output],
                                    check=True, capture_output=True, text=True).stdout for output in (profile, start)]
    counts = inclusive_counts(annotated[0])
    total, start_total = program_total(annotated[0]), program_total(annotated[1])
    shares = {name: total_of(counts, keys) for name, keys in PARTS}
    shares["process start and exit (heavesim --version)"] = start_total
    shares["recording (the rest)"] = total - sum(shares.values())
    print(f"{total:,} instructions in one run of {arguments.case}")
    print_shares(shares.items(), total)
    print("  named parts of the recording:")
    print_shares([(name, total_of(counts, keys)) for name, keys in DETAILS], total)
    # The integrating thread alone (scripts/recording_share.py's view, counted): everything
    # but the helper threads, whose work is all recording and runs beside it on a second core.
    helpers = total_of(counts, ("BackgroundWorker::loop",))
    if helpers == 0:
        # A run too short for helper threads (Recorder::why_samples_in_line), or a build that
        # inlined BackgroundWorker::loop: then this split would silently be the process's.
        print("  (no helper thread found: BackgroundWorker::loop has no instructions; the integrating"
              " thread's split below is the whole process's)")
    main_thread = total - helpers
    main_shares = [(name, count) for name, count in shares.items() if name != "recording (the rest)"]
    main_shares.append(("recording (the rest)", main_thread - sum(count for _, count in main_shares)))
    print(f"{main_thread:,} of them on the integrating thread (the helper threads' {helpers:,} run beside it):")
    # That thread evaluates samples too whenever the samples' thread is busy
    # (Recorder::evaluate_next_ready_sample): how many depends on the schedule, and Valgrind runs
    # one thread at a time, so it takes more of them here than in a run (`heavesim run`
    # prints the run's split).
    print("  (with the samples that thread evaluated while the samples' thread was busy: under"
          " Valgrind's one-thread-at-a-time schedule, more than in a run)")
    print_shares(main_shares, main_thread)


if __name__ == "__main__":
    main()
