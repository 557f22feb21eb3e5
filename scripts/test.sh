#!/usr/bin/env bash
# Builds and runs the whole test suite: the GoogleTest/CTest suite on the Release
# build, the validation table, then the sanitizer pass (scripts/sanitize.sh) and a short
# fuzzing pass (scripts/fuzz.sh: the committed regression inputs, then 45 s per target).
#   scripts/test.sh           everything
#   scripts/test.sh --fast    skip the sanitizer and fuzzing builds
set -euo pipefail
cd "$(dirname "$0")/.."
# Each stage's end is printed with the seconds since the start (CI's budget is 45 min).
SECONDS=0
stage_done() { echo "test: $1 done at ${SECONDS} s"; }
scripts/setup.sh
stage_done "setup"
# The programs the suite runs (the benchmarks are built by scripts/build.sh alone).
scripts/build.sh heavesim heavesim_tests
stage_done "Release build"
(cd build && ctest --output-on-failure -j "$(nproc)")
stage_done "Release CTest"
build/heavesim validate -j "$(nproc)"
stage_done "validation table"
if [[ "${1:-}" != "--fast" ]]; then
  scripts/sanitize.sh
  stage_done "sanitizer build and CTest"
  scripts/fuzz.sh 45
  stage_done "fuzzing"
fi
echo "test: all passed"
