#!/usr/bin/env bash
# The main job: installs what is missing, builds (Release), runs the default case and
# writes its results and plots to results/.
#   scripts/main.sh [case.yaml]
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh heavesim
case_file=${1:-cases/validation/two_link.yaml}
name=$(basename "$case_file" .yaml)
mkdir -p results
build/heavesim run "$case_file" -o "results/$name.h5" --csv results
/usr/bin/python3 scripts/plot_run.py "results/$name.h5" -o results
