#!/usr/bin/env bash
# Counted 2-thread efficiency of the pour (issue 19): callgrind at 1 and 2 threads from the box-fill
# sample's 0.1 s checkpoint (STATE; made once into WORKDIR when not given), a run of START steps
# (start-up) and one of START + STEPS; regions.py takes long less short a thread and prints T1,
# the serial part, each region's two threads and T1 / (2 T2). Counted, not timed: valgrind runs the threads in turn, so it holds under any load.
# usage: tools/bench/pour/count_efficiency.sh BIN [STEPS=400] [STATE] [WORKDIR=/tmp/pour_eff]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
bin=$(realpath "$1"); steps=${2:-400}
work=${4:-/tmp/pour_eff}; mkdir -p "$work"
source "$here/state.sh"
state=${3:-$(pour_state "$bin" "$work")}
start=10  # steps in the short run: the start-up and the first rebuild
dt=$pour_dt
t0=0.1  # the state's time
pour_yaml "$work"
run() {  # threads steps
  local tag=$1.$2; rm -rf "$work/out.$tag" "$work/cg.$tag"-*
  OMP_WAIT_POLICY=passive valgrind --tool=callgrind --separate-threads=yes \
    --callgrind-out-file="$work/cg.$tag" "$bin" run "$work/pour.yaml" --resume "$state" \
    --out "$work/out.$tag" --force --until "$(python3 -c "print($t0 + ($2 + 0.5) * $dt)")" \
    --threads "$1" --fixed-threads > "$work/log.$tag" 2>&1
  grep 'steps in' "$work/log.$tag"
}
for th in 1 2; do run $th $start; run $th $((start + steps)); done
python3 "$here/regions.py" "$work/cg.1.$start" "$work/cg.1.$((start + steps))" \
  "$work/cg.2.$start" "$work/cg.2.$((start + steps))"
