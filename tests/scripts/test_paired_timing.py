"""scripts/paired_timing.py, the paired whole-process timing behind docs/performance.md's
ratios, against commands whose cost is known beforehand: two sleeps (wall time, no CPU),
two shell loops of N and 2N iterations (CPU in proportion), a process that touches 200 MiB
(its peak), and a command past the time bound or not there at all. Run from CTest
(tests/CMakeLists.txt: PairedTiming.*).
"""
import os
import subprocess
import sys
import time
import unittest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCRIPT = os.path.join(ROOT, "scripts", "paired_timing.py")


def paired_timing(*arguments, timeout=120):
    return subprocess.run([sys.executable, SCRIPT, *arguments], capture_output=True, text=True, timeout=timeout)


def row(output, label):
    """(min, median, max) of the row `label` ("A/B wall", "A peak MiB", ...)."""
    for line in output.splitlines():
        if line.startswith(label + " ") and len(line.split()) >= 3:
            return tuple(float(x) for x in line.split()[-3:])
    raise AssertionError(f"no row '{label}' in:\n{output}")


def loop_body(iterations):
    return f"i=0; while [ $i -lt {iterations} ]; do i=$((i+1)); done"


class WallAndCpuRatios(unittest.TestCase):
    def test_two_sleeps_give_the_ratio_of_their_durations_and_no_cpu(self):
        # 0.3 s against 0.1 s, each plus its start (~10 ms here, more on a busy machine): ~2.8,
        # not 3; 20 ms more start for B alone in most pairs would still give 2.4.
        result = paired_timing("-n", "5", "--vs", "sleep 0.1", "--", "sleep", "0.3")
        self.assertEqual(result.returncode, 0, result.stderr)
        ratio = row(result.stdout, "A/B wall")[1]
        self.assertGreater(ratio, 2.0, result.stdout)
        self.assertLess(ratio, 3.2, result.stdout)
        self.assertLess(row(result.stdout, "A cpu s")[1], 0.05, result.stdout)

    def test_a_loop_twice_as_long_takes_twice_the_cpu(self):
        # CPU time, not wall: steady however busy the machine is.
        result = paired_timing("-n", "5", "--vs", f"sh -c '{loop_body(200000)}'", "--", "sh", "-c", loop_body(400000))
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertGreater(row(result.stdout, "B cpu s")[1], 0.05, result.stdout)  # long enough to resolve
        ratio = row(result.stdout, "A/B cpu")[1]
        self.assertGreater(ratio, 1.6, result.stdout)
        self.assertLess(ratio, 2.4, result.stdout)


class PeakMemory(unittest.TestCase):
    def test_a_process_that_touches_200_mib_peaks_above_it(self):
        touch = "b = bytearray(200 * 2**20); b[::4096] = b'x' * len(b[::4096])"
        result = paired_timing("-n", "3", "--vs", "true", "--", sys.executable, "-c", touch)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertGreater(row(result.stdout, "A peak MiB")[1], 200.0, result.stdout)
        self.assertLess(row(result.stdout, "B peak MiB")[1], 100.0, result.stdout)


class Bounds(unittest.TestCase):
    def test_the_time_bound_kills_the_command_and_exits_3(self):
        start = time.monotonic()
        result = paired_timing("-n", "3", "--timeout", "0.5", "--", "sleep", "30")
        self.assertEqual(result.returncode, 3, result.stdout + result.stderr)
        self.assertLess(time.monotonic() - start, 10.0)
        self.assertIn("ended by the time bound", result.stdout)

    def test_a_command_that_cannot_start_exits_2(self):
        result = paired_timing("--", "/nonexistent/command")
        self.assertEqual(result.returncode, 2, result.stdout + result.stderr)
        self.assertIn("cannot start /nonexistent/command", result.stderr)

    def test_the_commands_exit_codes_are_printed_not_acted_on(self):
        result = paired_timing("-n", "2", "--vs", "true", "--", "false")
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("A: false   exit codes [1]", result.stdout)


if __name__ == "__main__":
    unittest.main()
