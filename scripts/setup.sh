#!/usr/bin/env bash
# Installs the Debian 12 packages heavesim needs, if they are missing.
#   scripts/setup.sh           build, test, plotting and report dependencies (Chromium for its test)
#   scripts/setup.sh --peers   also MuJoCo and DART, for the side-by-side benchmarks
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev libsundials-dev libsuitesparse-dev libhdf5-dev libyaml-cpp-dev libcli11-dev libfmt-dev libmuparser-dev
  nettle-dev                   # SHA-256 of cases (app/case/sha256.cpp)
  libfftw3-dev                 # the Welch spectra's real transforms (signal/hann_segment.cpp)
  libgtest-dev libgmock-dev libbenchmark-dev
  clang-14 libclang-rt-14-dev  # libFuzzer and the sanitizer runtimes (scripts/fuzz.sh)
  python3-numpy python3-scipy python3-h5py python3-matplotlib
  libopenmpi-dev openmpi-bin   # heavesim sweep across MPI ranks (mpirun)
  pybind11-dev python3-dev     # the heavesim Python package
  python3-yaml                 # heavesim report reads the resolved case (scripts/report.py)
  chromium fonts-dejavu-core   # the report's headless-browser test (CTest Report.*)
  valgrind                     # the race detector the threads' test runs under (CTest Threads.*)
)
if [[ "${1:-}" == "--peers" ]]; then
  packages+=(libmujoco-dev libqhull-dev libdart-dev libbullet-dev libsiconos-numerics-dev)
fi

missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
if ((${#missing[@]} == 0)); then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

echo "setup: installing ${missing[*]}"
if [[ $(id -u) -eq 0 ]]; then
  sudo=()
elif command -v sudo >/dev/null; then
  sudo=(sudo)
else
  echo "setup: need root (or sudo) to install: ${missing[*]}" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
