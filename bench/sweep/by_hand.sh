#!/bin/sh
# The 12 runs of drilling_periods.yaml, one `heavesim run` each, one after the other (or
# JOBS at once): what a user would type without `heavesim sweep`.
#     bench/sweep/by_hand.sh BINARY OUTPUT_DIRECTORY [JOBS]
binary=$1
out=$2
jobs=${3:-1}
root=$(dirname "$0")/../..
mkdir -p "$out"
seq 6 17 | xargs -P "$jobs" -I{} "$binary" run "$root/cases/drilling.yaml" -q -o "$out/T{}.h5" --set parameters.T={}
