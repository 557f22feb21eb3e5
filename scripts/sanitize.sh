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
(cd build-checked && ctest --output-on-failure -j "$(nproc)")
echo "sanitize: no sanitizer reports"
