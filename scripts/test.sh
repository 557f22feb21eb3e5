#!/usr/bin/env bash
# Builds and runs the whole test suite: the GoogleTest/CTest suite on the Release
# build, the validation table, then the sanitizer pass (scripts/sanitize.sh) and a short
# fuzzing pass (scripts/fuzz.sh: the committed regression inputs, then 45 s per target).
#   scripts/test.sh           everything
#   scripts/test.sh --fast    skip the sanitizer and fuzzing builds
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
# The programs the suite runs (the benchmarks are built by scripts/build.sh alone).
scripts/build.sh heavesim heavesim_tests
(cd build && ctest --output-on-failure -j "$(nproc)")
build/heavesim validate
if [[ "${1:-}" != "--fast" ]]; then
  scripts/sanitize.sh
  scripts/fuzz.sh 45
fi
echo "test: all passed"
