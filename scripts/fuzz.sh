#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/) in the checked build (scripts/checked_build.sh:
# clang 14, AddressSanitizer + UBSan; build-checked/), replays the committed regression
# inputs, then fuzzes each target for a bounded time from a seed corpus gathered from
# the project's own cases and data files.
#   scripts/fuzz.sh [SECONDS_PER_TARGET] [TARGET...]
#     SECONDS_PER_TARGET  default 60
#     TARGET              fuzz_case fuzz_expression fuzz_wamit fuzz_bemio fuzz_capytaine fuzz_mksim (default all)
# Prints per target the executions, libFuzzer's final coverage (cov: edges, ft: features)
# and the findings (crash, unexpected exception, leak, timeout, out-of-memory: saved under
# build-checked/work/<target>/findings/; each target fuzzes its whole budget past findings).
# Exits 1 if a regression input fails or a finding is in this project's code (findings
# inside libhdf5 are listed, not failed on).
set -euo pipefail
cd "$(dirname "$0")/.."
source_dir=$PWD
seconds=${1:-60}
shift || true
all_targets=(fuzz_case fuzz_expression fuzz_wamit fuzz_bemio fuzz_capytaine fuzz_mksim)
targets=("$@")
((${#targets[@]} > 0)) || targets=("${all_targets[@]}")

# ---------------------------------------------------------------- build
build_dir=build-checked  # the checked build, shared with the sanitizer pass
work_dir=$source_dir/$build_dir/work
scripts/checked_build.sh "${targets[@]}"

# ---------------------------------------------------------------- seeds
# Seeds are the project's own inputs, gathered afresh each run (nothing large is
# committed); fuzz/seeds/<target>/ adds the few that exercise what no project file does.
gather_seeds() {
  local target=$1 seeds=$2
  rm -rf "$seeds"
  mkdir -p "$seeds"
  local files=()
  case $target in
    fuzz_case) mapfile -t files < <(find cases tests/cases tests/bad_cases -name '*.yaml') ;;
    fuzz_wamit) mapfile -t files < <(find data tests/bem tests/bad_bem -regex '.*\.\(1\|3\|hst\)') ;;
    fuzz_bemio) mapfile -t files < <(find data tests/bem tests/bad_bem -name '*.h5') ;;
    fuzz_capytaine) mapfile -t files < <(find data tests/bem tests/bad_bem -name '*.nc') ;;
    fuzz_mksim) mapfile -t files < <(find cases tests/bad_mksim -name '*.mks') ;;
  esac
  [[ -d fuzz/seeds/$target ]] && mapfile -t -O "${#files[@]}" files < <(find "fuzz/seeds/$target" -type f)
  local file
  for file in "${files[@]}"; do cp "$file" "$seeds/$(echo "$file" | tr / _)"; done
}

# A dictionary of the case schema's keys and the words the readers accept, taken from the
# sources so that it follows the schema; the HDF5 formats' dataset names likewise.
write_dictionary() {
  local target=$1 dictionary=$2
  case $target in
    fuzz_case)
      {
        grep -ohE '\{"[a-z_0-9]+",' app/case/case_schema.cpp app/forces/*.cpp | sed -E 's/\{"(.*)",/"\1: "/'
        grep -ohE '"[a-z][a-z0-9_]{2,30}"' app/case/*.cpp app/forces/*.cpp
        printf '%s\n' '"#%%\x0A"' '"include: part.yaml\x0A"' '"&a "' '"*a"' '"<<: "' '"!!binary "' '"1e308"' \
          '"-1e-300"' '".nan"' '"-.inf"' '"4294967296"' '"[0, 0, 1]"' '"\x0A  - "' '"{}"'
      } | sort -u >"$dictionary" ;;
    fuzz_expression)
      printf '%s\n' '"sin("' '"cos("' '"tan("' '"sqrt("' '"exp("' '"log("' '"ln("' '"log10("' '"abs("' '"sign("' \
        '"rint("' '"min("' '"max("' '"sum("' '"avg("' '"deg("' '"rad("' '"pi"' '"_pi"' '"_e"' '"t"' '"?"' '":"' \
        '"^"' '"&&"' '"||"' '"1e308"' '"1e-308"' '"="' '"\x0A"' '","' >"$dictionary" ;;
    fuzz_wamit)
      printf '%s\n' '"-1"' '"0"' '"1.0E+00"' '"-.1E-308"' '"NaN"' '"Infinity"' '"1e400"' '"  6"' '"\x0A"' \
        '" 1 1 "' '"2147483648"' >"$dictionary" ;;
    fuzz_mksim)
      printf '%s\n' '"MODEL "' '"ENDMODEL"' '"SYSTEM"' '"KINEMATIC ANALYSIS"' '"starting time = "' \
        '"ending time = "' '"print interval = "' '"nr tolerance = "' '"assembly tolerance = "' '"BODY "' \
        '"{ ground }"' '"center of gravity = "' '"par = "' '"triad "' '"associated body = "' '"origin = "' \
        '"revolute joint "' '"spherical joint "' '"translational joint "' '"universal joint "' \
        '"cylindrical joint "' '"triad = "' '"driver "' '".x = "' '"TIME"' '"(0,0,0)"' '"{(0,0,0),(0,0,1),(1,0,0)}"' \
        '"//"' '"1e308"' '"-1e-300"' >"$dictionary" ;;
    fuzz_bemio | fuzz_capytaine)
      grep -ohE '"/?[a-zA-Z_][a-zA-Z0-9_/]{2,40}"' io/bem/*.cpp | sort -u >"$dictionary" ;;
  esac
}

max_len_of() {
  case $1 in
    fuzz_case) echo 16384 ;;
    fuzz_expression) echo 512 ;;
    fuzz_mksim) echo 8192 ;;
    fuzz_wamit) echo 32768 ;;
    *) echo 65536 ;;
  esac
}

# ---------------------------------------------------------------- run
# Where a finding happened: the first frame of the failing stack that is either this
# project's source (a file:line under the source tree; header code inlined into it, the
# C++ library's and Eigen's, is passed over to the project frame that called it) or
# libhdf5's. The sanitizer's, libc's, libFuzzer's frames and those of the libraries
# libhdf5 calls (zlib for deflated chunks) are passed over the same way. A finding
# inside libhdf5 (its parser of a damaged file, e.g. H5HG_read on a damaged global heap)
# is listed but not failed on: it is not this project's code, and the readers guard
# what they can before calling it (io/hdf5/hdf5_reader.cpp). A stack with neither is
# reported as it is and fails the run.
# Only the stacks where something went wrong are placed: an AddressSanitizer error's
# first stack, UBSan's, a timeout's, each leak's allocation. The stacks that describe
# the memory involved ("freed by", "previously allocated by", "allocated by", a
# thread's creation) are not where it failed: a read inside libhdf5 through a garbage
# pointer lands in memory our code freed earlier, and that free is not the finding.
first_frames() {  # stdin: sanitizer report(s); stdout: each failing stack's deciding frame
  # (not the heap profile an out-of-memory report ends with: what was live, not where it failed)
  awk -v ours=" $source_dir/[^ ]*:[0-9]+" '
    /^Live Heap Allocations/ { exit }
    /(freed by thread|allocated by thread|created by T[0-9]+ here)/ { describing = 1; next }
    /ERROR:|runtime error|(Direct|Indirect) leak of|ALARM|deadly signal/ { describing = 0 }
    /^ +#0 0x/ { stack++; placed[stack] = describing; first[stack] = $0 }
    /^ +#[0-9]+ 0x/ {
      if (placed[stack]) next
      if ($0 ~ /libhdf5/ || $0 ~ ours) { print; placed[stack] = 1 }
    }
    END { for (s = 1; s <= stack; s++) if (!placed[s]) print "unplaced stack:" first[s] }'
}
# The finding replayed alone: its failing stack's deciding frame, or "not reproduced alone".
# The replay refuses any single allocation above 512 MiB (four times the readers' bound on
# one dataset, io/hdf5/hdf5_reader.cpp), so that an out-of-memory is reported with the
# stack of the allocation that caused it. Past the RSS limit libFuzzer reports no stack:
# CI's run of 2026-11-29 counted such a finding as ours for want of a frame, and replays
# here of the same class placed them all in libhdf5 (single allocations of 1.9 to 21 GB
# from damaged lengths in H5C_protect and the variable-length string conversion).
# When the replay itself crosses the RSS limit first (no stack again: CI of 2026-12-01, a
# BEMIO input whose 2.7 GB of RSS came before HDF5's 21 GB variable-length conversion), it
# runs once more with room up to 8 GiB, for the allocation limit to catch the culprit.
where_found() {
  local binary=$1 input=$2 report rss_limit
  for rss_limit in 2048 8192; do
    if report=$(ASAN_OPTIONS=${ASAN_OPTIONS//:log_path=*/} "$binary" -runs=1 -rss_limit_mb=$rss_limit \
      -malloc_limit_mb=512 -timeout=20 "$input" 2>&1); then
      echo "not reproduced alone"
      return
    fi
    [[ "$report" == *"out-of-memory (used:"* ]] || break
  done
  echo "$report" | first_frames | head -1
}

asan_options=${ASAN_OPTIONS:-detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$source_dir/fuzz/lsan.supp:print_suppressions=0}
failed=0
summary=()
for target in "${targets[@]}"; do
  binary=$build_dir/fuzz/$target
  dir=$work_dir/$target
  # libhdf5 has no frame pointers: its allocations need full stacks for the leak
  # suppressions to see where they come from (slow; only the HDF5 targets need it).
  export ASAN_OPTIONS=$asan_options
  [[ $target == fuzz_bemio || $target == fuzz_capytaine ]] && ASAN_OPTIONS+=:fast_unwind_on_malloc=0
  # Every sanitizer report of the fuzzing processes, whole, one file per process: a
  # finding that does not happen when its input runs alone (state libhdf5 kept from
  # earlier inputs) is placed by the stacks its process reported.
  ASAN_OPTIONS+=:log_path=$dir/reports/sanitizer
  rm -rf "$dir/findings" "$dir/findings.txt" "$dir/reports"
  mkdir -p "$dir/corpus" "$dir/findings" "$dir/reports"
  # Every committed finding must now be handled (each input run once).
  regressions=(fuzz/regressions/$target/*)
  regression_result="no regression inputs"
  if [[ -e "${regressions[0]}" ]]; then
    if "$binary" -runs=1 -timeout=30 -rss_limit_mb=2048 "${regressions[@]}" >"$dir/regressions.log" 2>&1; then
      regression_result="${#regressions[@]} regression inputs pass"
    else
      regression_result="REGRESSION INPUT FAILS (see $dir/regressions.log)"
      failed=1
    fi
  fi
  gather_seeds "$target" "$dir/seeds"
  write_dictionary "$target" "$dir/dictionary"
  # -fork=1: one child process at a time that is restarted past each finding, so the
  # whole budget is fuzzed and every finding kept.
  echo "fuzz: $target for ${seconds}s ($regression_result)"
  "$binary" -max_total_time="$seconds" -timeout=20 -rss_limit_mb=2048 -max_len="$(max_len_of "$target")" \
    -dict="$dir/dictionary" -artifact_prefix="$dir/findings/" -print_final_stats=1 \
    -fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
    "$dir/corpus" "$dir/seeds" >"$dir/fuzz.log" 2>&1 || true
  # Executions and coverage: libFuzzer's last status line ("#N: cov: C ft: F ...").
  status_line=$(grep -aE '^#[0-9]+' "$dir/fuzz.log" | tail -1 || true)
  executions=$(echo "$status_line" | grep -oE '^#[0-9]+' | tr -d '#' || true)
  coverage=$(echo "$status_line" | grep -oE 'cov: [0-9]+ ft: [0-9]+' || true)
  ours=0 inside_hdf5=0 not_reproduced=0
  for finding in "$dir"/findings/*; do
    [[ -e "$finding" ]] || continue
    frame=$(where_found "$binary" "$finding" || true)
    if [[ "$frame" == "not reproduced alone" ]]; then
      # Placed below by its process's report (a leak or crash that needs libhdf5's state
      # from earlier inputs); an out-of-memory or timeout accumulated over a job's runs.
      not_reproduced=$((not_reproduced + 1))
      echo "fuzz: $target: not reproduced alone: $(basename "$finding")" >>"$dir/findings.txt"
    elif [[ "$frame" == *libhdf5* ]]; then
      inside_hdf5=$((inside_hdf5 + 1))
      echo "fuzz: $target: inside libhdf5: $(basename "$finding"):${frame#*in }" >>"$dir/findings.txt"
    else
      ours=$((ours + 1))
      echo "fuzz: $target: FINDING $(basename "$finding"):${frame:+${frame#*in }}" >>"$dir/findings.txt"
    fi
  done
  # Every stack of every report the fuzzing processes wrote, replayed or not: one whose
  # first frame of interest is not libhdf5's is this project's.
  for report in "$dir"/reports/sanitizer.*; do
    [[ -e "$report" ]] || continue
    while IFS= read -r frame; do
      [[ "$frame" == *libhdf5* ]] && continue
      ours=$((ours + 1))
      echo "fuzz: $target: FINDING in report $(basename "$report"):${frame#*in }" >>"$dir/findings.txt"
    done < <(first_frames <"$report")
  done
  line="$target: ${executions:-0} executions, ${coverage:-no coverage reported}, $ours findings"
  ((inside_hdf5 == 0)) || line+=" (+ $inside_hdf5 inside libhdf5)"
  ((not_reproduced == 0)) || line+=" (+ $not_reproduced not reproduced alone, their reports inside libhdf5)"
  line+=", $regression_result"
  if ((ours > 0)) || [[ -z "$executions" ]]; then
    line+=" -- FINDING (log: $dir/fuzz.log, inputs: $dir/findings/, where: $dir/findings.txt)"
    failed=1
  fi
  echo "fuzz: $line"
  # Where each of ours happened, in the run's own output (a CI log is all one may see).
  if ((ours > 0)); then
    grep -a 'FINDING' "$dir/findings.txt" | cut -c1-400 | sed 's/^/  /'
  fi
  summary+=("$line")
done
echo "fuzz: summary"
printf '  %s\n' "${summary[@]}"
exit $failed
