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
# Some tests are long runs of code that shorter tests already take through the sanitizers;
# the Release suite (and `heavesim validate`) still holds every one of them at its bar.
# Under the sanitizers (clang -O1, Eigen's assertions, ASan) they took, in the sanitizer
# CTest of a clean-clone CI run on 2026-11-30 (471 s wall, 897 s CPU, 2 cores):
#   P4  2 x 1000 contact steps of 20 stacked cubes (P3 runs the same stepper and LCP
#       solver): 342 s in an earlier run (Release 7 s);
#   A01 a pendulum for 2000 s (K3 runs the same pendulum and integrators): 61 s earlier;
#   A05 the flyball governor, 10 s of IDA and 200,000 HHT steps: 202 s (Release 3 s);
#       A03 and A04 run IDA's closed-loop path, A04 HHT's;
#   L5  the over-constrained parallelogram, 10 s of HHT at 0.1 ms and Dormand-Prince:
#       94 s (Release 1 s); A04 runs a redundant row through both integrators, and
#       NoMalloc.HhtStepsDoNotAllocate a planar four-bar closed by a revolute loop joint
#       (whose out-of-plane rows are zero) through HHT;
#   K5  a free body and a symmetric top for 100 s each: 36 s (Release 0.6 s); K6 runs
#       the free joint's algorithms in random trees, K3 the integrators;
#   Report.IrregularSeaPageHasItsRaos  a 3-hour sea of 1000 components, its report and
#       `heavesim rao`: 129 s (Release 11 s); the estimator's and the rao command's own
#       tests (CrossSpectrum, RaoCommand) run here, and the hydro rows run the semi.
(cd build-checked && ctest --output-on-failure -j "$(nproc)" \
  -E 'ValidationSuite\.EveryRowPassesItsBar/"(P4|A01|A05|L5|K5)"$|^Report\.IrregularSeaPageHasItsRaos$')
echo "sanitize: no sanitizer reports"
