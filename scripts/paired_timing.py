#!/usr/bin/python3
"""Times whole commands from outside, two of them in alternation, and gives their ratio.

    /usr/bin/python3 scripts/paired_timing.py [-n RUNS] [--warmup W] [--timeout S] [--vs 'COMMAND_B'] -- COMMAND_A [ARG ...]

Each run is one process, timed from its start to its exit (start-up and set-up included):
wall seconds from a monotonic clock read just before the start and just after the child
is reaped; user and system seconds and the peak resident memory from the kernel's
accounting of the finished child (wait4: the child and the descendants it waited for).
With --vs, A and B run in turn, A B A B ..., after W unrecorded warm-up runs of each, and
the ratio A/B is taken pair by pair: on a shared machine whose speed drifts, a pair's two
runs see about the same machine, so the median of the pair ratios is steadier than the
ratio of the medians. Every figure is printed as min, median and max over the runs; quote
the median. Commands get no shell (COMMAND_B is split as a shell splits words: write
`sh -c '...'` for a pipe, `env X=1 CMD` for a variable), an empty standard input, and
their output is thrown away. --timeout bounds the whole call: the running command's
process group is killed and the finished runs are printed.

Exit status: 0 every run finished (the commands' own exit codes are printed, not acted
on); 2 bad arguments or a command that cannot start; 3 the time bound ended the call.

docs/performance.md's paired ratios are this script's (and, before 2026-12-02, those of a
tool of the same method).
"""
import argparse
import os
import resource
import shlex
import signal
import statistics
import subprocess
import sys
import threading
import time


class TimeBound(Exception):
    pass


class CannotStart(Exception):
    pass


def run_once(command, deadline):
    """(wall s, user s, system s, peak MiB, exit code) of one run of `command`."""
    start = time.monotonic()
    try:
        child = subprocess.Popen(command, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                                 stderr=subprocess.DEVNULL, start_new_session=True)
    except OSError as error:
        raise CannotStart(f"paired_timing: cannot start {command[0]}: {error.strerror}") from None
    # Blocked in wait4 while the command runs (no polling beside it); a timer kills the
    # command's process group at the call's time bound.
    killed = threading.Event()

    def kill():
        killed.set()
        os.killpg(child.pid, signal.SIGKILL)

    timer = threading.Timer(max(deadline - time.monotonic(), 0.0), kill)
    timer.start()
    _, status, usage = os.wait4(child.pid, 0)
    wall = time.monotonic() - start
    timer.cancel()
    if killed.is_set():
        child.returncode = -signal.SIGKILL
        raise TimeBound()
    child.returncode = os.waitstatus_to_exitcode(status)  # reaped here: Popen must not wait again
    return wall, usage.ru_utime, usage.ru_stime, usage.ru_maxrss / 1024.0, child.returncode


def spread(values):
    return min(values), statistics.median(values), max(values)


def print_row(label, values, digits):
    low, middle, high = spread(values)
    print(f"{label:16s} {low:10.{digits}f}  {middle:10.{digits}f}  {high:10.{digits}f}")


def main():
    if "--" not in sys.argv:
        print("paired_timing: expected -- COMMAND [ARG ...]", file=sys.stderr)
        return 2
    split = sys.argv.index("--")
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("-n", "--runs", type=int, default=5)
    parser.add_argument("--warmup", type=int, default=1)
    parser.add_argument("--timeout", type=float, default=100.0)
    parser.add_argument("--vs", default=None, help="the second command, B (one string)")
    arguments = parser.parse_args(sys.argv[1:split])
    command_a = sys.argv[split + 1:]
    if not command_a or arguments.runs < 1 or arguments.warmup < 0 or arguments.timeout <= 0:
        print("paired_timing: expected RUNS >= 1, WARMUP >= 0, TIMEOUT > 0 and a command", file=sys.stderr)
        return 2
    commands = {"A": command_a}
    if arguments.vs is not None:
        commands["B"] = shlex.split(arguments.vs)
        if not commands["B"]:
            print("paired_timing: --vs names no command", file=sys.stderr)
            return 2
    deadline = time.monotonic() + arguments.timeout
    runs = {label: [] for label in commands}
    ended_early = False
    try:
        for _ in range(arguments.warmup):
            for command in commands.values():
                run_once(command, deadline)
        for _ in range(arguments.runs):
            finished = {label: run_once(command, deadline) for label, command in commands.items()}
            for label, result in finished.items():  # a pair counts only whole
                runs[label].append(result)
    except TimeBound:
        ended_early = True
    except CannotStart as error:
        print(error, file=sys.stderr)
        return 2

    print(f"{len(runs['A'])} runs{' of each, alternating' if 'B' in commands else ''}"
          f"{' (ended by the time bound)' if ended_early else ''}:  min  median  max")
    # The kernel counts the child's peak from its fork, a copy of this process until the exec.
    print(f"(peak memory cannot read below this script's own, {resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0:.1f} MiB)")
    for label in commands:
        if not runs[label]:
            continue
        print(f"{label}: {shlex.join(commands[label])}   exit codes {sorted({run[4] for run in runs[label]})}")
        columns = list(zip(*runs[label]))
        print_row(f"{label} user s", columns[1], 3)
        print_row(f"{label} sys s", columns[2], 3)
        print_row(f"{label} cpu s", [u + s for u, s in zip(columns[1], columns[2])], 3)
        print_row(f"{label} wall s", columns[0], 3)
        print_row(f"{label} peak MiB", columns[3], 1)
    if "B" in commands and runs["A"]:
        for name, ratio in (("user", lambda r: r[1]), ("cpu", lambda r: r[1] + r[2]), ("wall", lambda r: r[0])):
            pairs = [ratio(a) / ratio(b) for a, b in zip(runs["A"], runs["B"]) if ratio(b) > 0]
            if pairs:
                print_row(f"A/B {name}", pairs, 4)
    return 3 if ended_early else 0


if __name__ == "__main__":
    sys.exit(main())
