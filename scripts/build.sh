#!/usr/bin/env bash
# Configures (Release) and builds heavesim in build/ (or $HEAVESIM_BUILD_DIR).
#   scripts/build.sh [cmake target ...]
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${HEAVESIM_BUILD_DIR:-build}
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
if [[ ! -f "$build_dir/CMakeCache.txt" ]]; then
  cmake -S . -B "$build_dir" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release
fi
targets=()
for target in "$@"; do targets+=(--target "$target"); done
cmake --build "$build_dir" -j "$(nproc)" "${targets[@]}"
