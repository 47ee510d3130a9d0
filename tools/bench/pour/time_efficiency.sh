#!/usr/bin/env bash
# Two builds alternated on the pour (the box-fill sample from its 0.1 s checkpoint, to UNTIL s:
# 0.2 is 11,766 steps, ~1,000 rebuilds; the start-up, ~55e6 instructions, is then under 1%), each at
# 1 and 2 threads, ROUNDS rounds, printing polydem's own loop time (s, "N steps in X s") and each
# build's efficiency t(1) / (2 t(2)) a round. A quiet machine's figure: under load it is noise.
# usage: tools/bench/pour/time_efficiency.sh NEW_POLYDEM OLD_POLYDEM [ROUNDS=5] [UNTIL=0.2] [STATE: made from the sample when not given]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
new=$1 old=$2 rounds=${3:-5} until=${4:-0.2}
work=$(mktemp -d)
source "$here/state.sh"
state=${5:-$(pour_state "$(realpath "$new")" "$work")}
pour_yaml "$work"
export GOMP_SPINCOUNT=${GOMP_SPINCOUNT:-1000}  # both builds alike (polydem's own default)
loop_seconds() {  # binary threads
  rm -rf "$work/out"
  "$1" run "$work/pour.yaml" --out "$work/out" --resume "$state" --force --until "$until" \
    --threads "$2" --fixed-threads 2>&1 | sed -n 's/.* steps in \([0-9.]*\) s.*/\1/p' | head -1
}
for ((r = 0; r < rounds; ++r)); do
  n1=$(loop_seconds "$new" 1) o1=$(loop_seconds "$old" 1) n2=$(loop_seconds "$new" 2) o2=$(loop_seconds "$old" 2)
  echo "new_1t $n1 old_1t $o1 new_2t $n2 old_2t $o2 eff_new $(python3 -c "print(round($n1 / (2 * $n2), 3))")" \
    "eff_old $(python3 -c "print(round($o1 / (2 * $o2), 3))")"
done
rm -rf "$work"
