#!/usr/bin/python3
"""The wall-time phases of one `heavesim run`, in real time: when the main thread enters
and leaves the functions that bound them, from Linux uprobes (Debian's linux-perf; root).

    /usr/bin/python3 scripts/run_phases.py [--binary build/heavesim] [--runs 9] CASE.yaml [--set k=v ...]

A uprobe is hit a few times a run (the bounding functions are entered once or twice), so
the run keeps its speed (unlike a sampling profile with call graphs, which doubles the
drilling run's wall time and cannot say when a thread waits). Per run: process start (exec
to the first read_case), case and scenes (the case read, the scene built, the result file
created with its metadata, the second scene for the samples' evaluation), the recorder's
constructor (its channels), before the first step (the sample batches, the integrator made,
and the result file's layout when the samples are evaluated in line; beside, the layout is
the samples' thread's first job, inside run_simulation), run_simulation (the integration,
and the waits for the samples' evaluation beside it), the
end of the run (Recorder::finish: the last block's statistics, the summary), the file's
close, and the exit. Prints each phase's median over the runs and its share of the median
total; docs/performance.md quotes it.
"""
import os
import statistics
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from recording_share import case_parser, run_line  # noqa: E402  (the same command line)

# The functions whose entries and returns bound the phases, by their demangled names.
FUNCTIONS = {
    "read_case": "heavesim::read_case(",
    "recorder": "heavesim::Recorder::Recorder(",
    "run_simulation": "heavesim::run_simulation(",
    "finish": "heavesim::Recorder::finish(",
    "close": "heavesim::ResultFile::close(",
}
PHASES = [  # name, from (event), to (event); events are "<function>>" (entry) or "<function><" (return)
    ("process start (exec to reading the case)", "exec", "read_case>"),
    ("case and scenes", "read_case>", "recorder>"),
    ("recorder constructor (channels)", "recorder>", "recorder<"),
    ("before the first step (batches, integrator; the layout if in line)", "recorder<", "run_simulation>"),
    ("run_simulation (integration, waits for the samples)", "run_simulation>", "run_simulation<"),
    ("after the integration", "run_simulation<", "finish>"),
    ("end of run (Recorder::finish)", "finish>", "finish<"),
    ("result file's close", "close>", "close<"),
    ("exit", "close<", "exit"),
]


def function_addresses(binary):
    """{function key: address} from the binary's symbol table (nm -C)."""
    listing = subprocess.run(["nm", "-C", "--defined-only", binary], capture_output=True, text=True, check=True).stdout
    found = {}
    for line in listing.splitlines():
        parts = line.split(" ", 2)
        if len(parts) < 3 or parts[1] not in ("T", "t"):
            continue
        for key, prefix in FUNCTIONS.items():
            if parts[2].startswith(prefix):
                found.setdefault(key, "0x" + parts[0].lstrip("0"))
    missing = sorted(set(FUNCTIONS) - set(found))
    if missing:
        sys.exit(f"run_phases: {binary} has no symbol for {', '.join(missing)}")
    return found


def phase_event(event):
    """"<key>>" for a probe "<key>_entry", "<key><" for "<key>_return" (recent perf names a
    return probe "<key>_return__return", older perf keeps the name given)."""
    if "_entry" in event:
        return event.split("_entry")[0] + ">"
    return event.split("_return")[0] + "<"


def perf(*arguments, **options):
    return subprocess.run(["perf", *arguments], capture_output=True, text=True, **options)


def main():
    parser = case_parser(__doc__)
    parser.add_argument("--runs", type=int, default=9)
    arguments = parser.parse_args()
    binary = os.path.realpath(arguments.binary)
    addresses = function_addresses(binary)
    group = "heavesim_phases"
    perf("probe", "-q", "-d", f"{group}:*")
    try:
        for key, address in addresses.items():
            for suffix, probe in (("entry", address), ("return", address + "%return")):
                added = perf("probe", "-q", "-x", binary, "-a", f"{group}:{key}_{suffix}={probe}")
                if added.returncode != 0:
                    sys.exit(f"run_phases: perf probe failed (root and linux-perf needed): {added.stderr.strip()}")
        durations = {name: [] for name, _, _ in PHASES}
        totals = []
        with tempfile.TemporaryDirectory() as directory:
            data = os.path.join(directory, "phases.data")
            for _ in range(arguments.runs):
                record = ["record", "-q", "-o", data, "-e", f"{group}:*", "-e", "sched:sched_process_exec",
                          "-e", "sched:sched_process_exit", "--", *run_line(arguments, os.path.join(directory, "r.h5"))]
                perf(*record, check=True)
                script = perf("script", "-i", data, "-F", "tid,time,event", check=True).stdout
                times, main_thread = {}, None
                for line in script.splitlines():
                    fields = line.split()
                    if len(fields) < 3:
                        continue
                    tid, time, event = fields[0], float(fields[1].rstrip(":")), fields[2].rstrip(":").split(":")[-1]
                    if event == "sched_process_exec":
                        main_thread = tid
                        times["exec"] = time
                    elif tid == main_thread and event == "sched_process_exit":
                        times["exit"] = time
                    elif tid == main_thread and event.startswith(tuple(f"{key}_" for key in addresses)):
                        times.setdefault(phase_event(event), time)  # the first entry and the first return
                if "exec" not in times or "exit" not in times:
                    print("run_phases: a run without its exec or exit event, left out", file=sys.stderr)
                    continue
                for name, start, end in PHASES:
                    if start in times and end in times:
                        durations[name].append(1e3 * (times[end] - times[start]))
                totals.append(1e3 * (times["exit"] - times["exec"]))
    finally:
        perf("probe", "-q", "-d", f"{group}:*")
    if not totals:
        sys.exit("run_phases: no run was timed")
    total = statistics.median(totals)
    print(f"{len(totals)} runs of {arguments.case}: median wall {total:.1f} ms (exec to exit)")
    for name, _, _ in PHASES:
        if durations[name]:
            median = statistics.median(durations[name])
            runs = "" if len(durations[name]) == len(totals) else f"  (in {len(durations[name])} runs only)"
            print(f"  {median:7.1f} ms  {100 * median / total:5.1f} %  {name}{runs}")
        else:
            print(f"      --- ms          {name}: not seen (the run took another path)")


if __name__ == "__main__":
    main()
