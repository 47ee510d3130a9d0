#!/usr/bin/env bash
# Work-precision diagram: cases with known answers (sphere-wall and sphere-sphere impacts,
# oblique impact, Hertz, cube corner and flat landings, free asymmetric top) across time
# steps; wall time and error per run. Writes tools/bench/accuracy/results.csv (machine,
# commit, case, dt_fraction, wall_s, error), or OUT_CSV, and accuracy.png (log-log error
# against run time, one line per case; reference.csv, an earlier commit's run, dashed beside it).
# usage: tools/bench/accuracy/run.sh [BUILD_DIR [OUT_CSV]]   (default: build; ~2 min on one core)
set -euo pipefail
cd "$(dirname "$0")/../../.."
build=${1:-build}
[ -x "$build/tests_validation" ] || bash tools/build.sh tests_validation
here=tools/bench/accuracy
raw=$(mktemp)
trap 'rm -f "$raw"' EXIT
POLYDEM_ACCURACY_CSV="$raw" "$build/tests_validation" "[.accuracy]" > /dev/null
machine=$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//; s/,//g')
commit=$(git rev-parse --short HEAD)$(git diff --quiet HEAD -- src include || echo +)
out=${2:-$here/results.csv}
{
  echo "machine,commit,$(head -1 "$raw")"
  tail -n +2 "$raw" | sed "s|^|$machine,$commit,|"
} > "$out"
[ "$out" = "$here/results.csv" ] || exit 0
reference=()
[ -f "$here/reference.csv" ] && reference=("$here/reference.csv")
/usr/bin/python3 "$here/plot.py" "$here/results.csv" "$here/accuracy.png" "${reference[@]}"
