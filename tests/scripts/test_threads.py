"""The recording threads checked by a race detector that does not share our reasoning.

A run records on four threads: the integrating one (which also evaluates samples, on its
own scene, while the next thread is busy), the recorder's evaluation of the
samples (on a second build of the scene, a batch of states at a time), the result file's
block writer and the recorder's block statistics (app/output/background_worker.hpp,
docs/architecture.md). Their correctness rests on a handshake: a worker reads only what
was handed to it (a batch of states, the last whole block), and the thread that handed it
waits for it (settle, wait) before it touches that again or the HDF5 file. Valgrind's Helgrind checks every access to memory that two threads
share against the happens-before order that the locks, condition variables and thread
starts and joins it observes give; an access that nothing orders is a "possible data
race", whether or not the schedule of this run made it go wrong. It runs the threads on
one core, one at a time in its own order, so the result file is also compared with an
ordinary run's: the threads' schedule must not change a number.

Run from CTest (tests/CMakeLists.txt: Threads.*), which sets HEAVESIM_BINARY and
HEAVESIM_TESTS_BINARY; needs valgrind (scripts/setup.sh installs it).
"""
import os
import subprocess
import sys
import tempfile
import unittest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BINARY = os.environ.get("HEAVESIM_BINARY", os.path.join(ROOT, "build", "heavesim"))
TESTS_BINARY = os.environ.get("HEAVESIM_TESTS_BINARY", os.path.join(ROOT, "build", "tests", "heavesim_tests"))
SUPPRESSIONS = os.path.join(ROOT, "tests", "scripts", "helgrind.supp")
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import compare_runs  # noqa: E402

# 250 s of the drilling case at its 0.05 s output interval: 5,001 samples, so four whole
# blocks of 1024 go to both workers while the integrating thread fills the next.
DRILLING_250_S = ["cases/drilling.yaml", "-q", "--set", "solver.t_end=250", "--set", "output.evaluate_after=100"]


def integer_attributes(path):
    """{object@name: value} of every integer attribute in the file (the root's included)."""
    import h5py
    import numpy as np
    found = {}
    with h5py.File(path, "r") as f:
        def collect(name, item):
            for key, value in item.attrs.items():
                value = np.asarray(value)
                if value.dtype.kind in "iu":
                    found[f"{name}@{key}"] = value.tolist()
        collect("/", f)
        f.visititems(collect)
    return found


def helgrind(command):
    """The command under Helgrind: (exit code, its output, Valgrind's report)."""
    run = subprocess.run(["valgrind", "--tool=helgrind", "--error-exitcode=9", f"--suppressions={SUPPRESSIONS}",
                          *command], capture_output=True, text=True, cwd=ROOT, timeout=900)
    return run.returncode, run.stdout, run.stderr


class HelgrindSeesNoRace(unittest.TestCase):
    def assert_clean(self, code, report):
        # Any Helgrind error fails, not only races: a condition variable signalled by a
        # thread that does not hold its mutex is one it cannot check.
        self.assertIn("ERROR SUMMARY: 0 errors", report, report[-6000:])
        self.assertEqual(code, 0, report[-6000:])

    def test_a_recorded_run_with_both_workers(self):
        with tempfile.TemporaryDirectory() as d:
            ordinary, checked = os.path.join(d, "ordinary.h5"), os.path.join(d, "helgrind.h5")
            run = subprocess.run([BINARY, "run", *DRILLING_250_S, "-o", ordinary], capture_output=True, text=True,
                                 cwd=ROOT, timeout=300)
            self.assertEqual(run.returncode, 0, run.stderr)
            code, _, report = helgrind([BINARY, "run", *DRILLING_250_S, "-o", checked])
            self.assert_clean(code, report)
            # Every number but the run's own timing, bit for bit, under another schedule.
            differences = compare_runs.differing_numbers(ordinary, checked)
            self.assertLessEqual(set(differences), {"summary@wall_time_s", "summary@real_time_factor"}, differences)

    def test_the_caller_evaluating_beside_the_samples_thread(self):
        # tests/app/test_result_file.cpp: the integrating thread evaluates a batch's first
        # samples on its own scene while the samples' thread records the batch before, and
        # hands the rows over; a failure on either thread ends the record in sample order.
        code, output, report = helgrind(
            [TESTS_BINARY, "--gtest_filter=Recorder.ASampleThatFailsEndsTheRecordWhereverItWasEvaluated"])
        self.assert_clean(code, report)
        self.assertIn("[  PASSED  ] 1 test", output)

    def test_the_worker_on_its_own(self):
        # The worker's own tests (tests/app/test_background_worker.cpp): its jobs'
        # writes read back after wait(), a failure handed over, the destructor's join.
        code, output, report = helgrind([TESTS_BINARY, "--gtest_filter=BackgroundWorker.*"])
        self.assert_clean(code, report)
        self.assertIn("[  PASSED  ] 4 tests", output)

    def test_the_loop_over_items_on_two_threads(self):
        # kernel/math/two_thread_loop.hpp (tests/kernel/test_two_thread_loop.cpp): items on
        # two threads, each item's then() on the caller's thread in order, reading what the
        # other thread's work wrote; failures handed over from either thread.
        code, output, report = helgrind([TESTS_BINARY, "--gtest_filter=TwoThreadLoop.*"])
        self.assert_clean(code, report)
        self.assertIn("[  PASSED  ] 6 tests", output)

    def test_the_shared_transform_plans(self):
        # signal/hann_segment.cpp: FFTW plans made on first use by whichever thread comes
        # first and used by all, transforms made and dropped on four threads at once
        # (tests/signal/test_hann_segment.cpp).
        code, output, report = helgrind(
            [TESTS_BINARY, "--gtest_filter=HannSegmentTransform.TransformsOnSeveralThreadsAtOnceAreTheWindowedDft"])
        self.assert_clean(code, report)
        self.assertIn("[  PASSED  ] 1 test", output)


class SamplesEvaluatedBeside(unittest.TestCase):
    def test_samples_evaluated_beside_are_those_evaluated_in_line(self):
        # A run pinned to one core evaluates every sample on the integrating thread, on the
        # integrated scene (Recorder::why_samples_in_line); an ordinary one on a second
        # build of the case, on a thread of its own. Two paths, one set of numbers. The
        # free semi and the compensated rig: hydro loads, compensator states, reactions; the
        # rig on a prescribed heave: a driver's expression of t, evaluated by both threads
        # (shared, its workspace once made them disagree, and moved the integration too).
        if len(os.sched_getaffinity(0)) < 2:
            self.skipTest("one core: every run evaluates its samples in line")
        cases = [DRILLING_250_S, ["cases/hydro/semisub_6dof_irregular_sea.yaml", "-q", "--set", "solver.t_end=600"],
                 ["cases/c2_prescribed_heave/h0_passive.yaml", "-q", "--set", "solver.t_end=150"]]
        with tempfile.TemporaryDirectory() as d:
            for case in cases:
                # `heavesim check` says which path each run takes.
                check_arguments = [argument for argument in case if argument != "-q"]
                for prefix, path in (([], "beside the integration"), (["taskset", "-c", "0"], "in line: one core")):
                    check = subprocess.run([*prefix, BINARY, "check", *check_arguments], capture_output=True,
                                           text=True, cwd=ROOT, timeout=60)
                    self.assertIn("samples evaluated " + path, check.stdout, (case[0], check.stdout))
                in_line, beside = os.path.join(d, "in_line.h5"), os.path.join(d, "beside.h5")
                for command in (["taskset", "-c", "0", BINARY, "run", *case, "-o", in_line],
                                [BINARY, "run", *case, "-o", beside]):
                    run = subprocess.run(command, capture_output=True, text=True, cwd=ROOT, timeout=300)
                    self.assertEqual(run.returncode, 0, run.stderr)
                differences = compare_runs.differing_numbers(in_line, beside)
                self.assertLessEqual(set(differences), {"summary@wall_time_s", "summary@real_time_factor"},
                                     (case[0], differences))
                # The counts too (samples written, end-stop events), which are integers.
                self.assertEqual(integer_attributes(in_line), integer_attributes(beside), case[0])


if __name__ == "__main__":
    unittest.main()
