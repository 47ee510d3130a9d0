#!/usr/bin/env bash
# Runs the libFuzzer targets (tests/fuzz) one after the other, SECONDS each, from the seed
# corpus tests/fuzz/corpus/NAME, on one core. New inputs go to build-fuzz/fuzz/NAME/corpus,
# findings (crash, leak, timeout > 10 s, > 2 GB) to build-fuzz/fuzz/NAME/crashes; the run goes
# on after a finding. A finding, once fixed, is saved in tests/fuzz/crashes/NAME, which CI replays.
# usage: tools/fuzz.sh [SECONDS] [TARGET...]   (default: 60 s; scene body_table shp stl vti checkpoint)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(scene body_table shp stl vti checkpoint)
bash tools/build_asan.sh --fuzz "${targets[@]/#/fuzz_}"
for t in "${targets[@]}"; do
  work="build-fuzz/fuzz/$t"
  mkdir -p "$work/corpus" "$work/crashes"
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    "build-fuzz/fuzz_$t" -fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
    -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -artifact_prefix="$work/crashes/" \
    "$work/corpus" "tests/fuzz/corpus/$t" > "$work/log" 2>&1 || true
  execs=$(grep -o '^#[0-9]*' "$work/log" | tail -1 | tr -d '#')
  echo "fuzz $t: ${execs:-0} executions in ${seconds} s, $(ls "$work/crashes" | wc -l) findings in $work/crashes"
done
