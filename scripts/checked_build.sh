#!/usr/bin/env bash
# The checked build, in build-checked/: clang 14, AddressSanitizer + UndefinedBehavior-
# Sanitizer on every source, libFuzzer's coverage feedback on every project library,
# and Eigen's runtime allocation check and assertions on (top CMakeLists.txt). One build
# serves both passes that need it: the sanitizer pass runs its tests
# (scripts/sanitize.sh) and the fuzzing pass its targets (scripts/fuzz.sh) on the same
# objects, so CI compiles the libraries once for both.
#   scripts/checked_build.sh TARGET...    build these targets (none: everything)
# Environment:
#   HEAVESIM_BUILD_LOCK=FILE    hold flock FILE while building (shared machines)
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=build-checked
if [[ ! -f "$build_dir/CMakeCache.txt" ]]; then
  launcher=()
  command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
  # -O1: the sanitizers' own advice (fast enough to fuzz, stacks still exact); -g1:
  # file:line in every report. NDEBUG: Eigen's assertions stay on through the checked
  # configuration (tests/kernel/no_malloc_config.hpp), which throws instead of aborting.
  CC=clang-14 CXX=clang++-14 cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
    -DHEAVESIM_SANITIZE=ON -DHEAVESIM_FUZZ=ON -DHEAVESIM_BUILD_BENCH=OFF "${launcher[@]}"
fi
build_targets=()
for target in "$@"; do build_targets+=(--target "$target"); done
lock=()
[[ -n "${HEAVESIM_BUILD_LOCK:-}" ]] && lock=(flock "$HEAVESIM_BUILD_LOCK")
"${lock[@]}" cmake --build "$build_dir" -j "$(nproc)" "${build_targets[@]}"
