#!/usr/bin/env bash
# AddressSanitizer + UndefinedBehaviorSanitizer pass: builds heavesim and the tests
# that read, write or buffer (every malformed case and data file, the result file,
# hull clipping, radiation memory, the validation table that runs every algorithm;
# the list is in tests/CMakeLists.txt) in the checked build (scripts/checked_build.sh,
# build-checked/: Eigen's allocation check and assertions on in every source) and runs
# them, with the no-allocation tests. Any sanitizer report, Eigen assertion or
# allocation fails the run.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/checked_build.sh heavesim heavesim_tests heavesim_no_malloc_tests
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# Two validation rows are long runs of code that shorter rows already take through the
# sanitizers: P4 (2 x 1000 contact steps of 20 stacked cubes; P3 runs the same stepper and
# LCP solver) and A01 (a pendulum for 2000 s; K3 runs the same pendulum and integrators).
# Under the sanitizers they took 342 s and 61 s of CI's 640 s here (Release: 8 s and 1 s;
# the Release suite and `heavesim validate` still run them at their bars).
(cd build-checked && ctest --output-on-failure -j "$(nproc)" -E 'ValidationSuite\.EveryRowPassesItsBar/"(P4|A01)"$')
echo "sanitize: no sanitizer reports"
