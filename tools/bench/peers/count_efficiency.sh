#!/usr/bin/env bash
# Counted 2-thread efficiency of a settled bed (issue 19), as tools/bench/pour/count_efficiency.sh
# counts the pour: callgrind --separate-threads at 1 and 2 threads from the bed's settled state, a
# run of 10 steps (start-up) and one of 10 + STEPS; regions.py takes long less short a thread and
# prints T1, the serial part, each region's two threads and T1 / (2 T2). SCENE as settled_bed.sh
# (spheres: the peers' bed, the default; cubes). Counted, not timed: the same under any load.
# usage: [SCENE=cubes] tools/bench/peers/count_efficiency.sh BIN [STEPS=300] [WORKDIR=/tmp/bed_eff]
set -euo pipefail
cd "$(dirname "$0")/../../.."
bin=$(realpath "$1"); steps=${2:-300}
work=${3:-/tmp/bed_eff}; mkdir -p "$work"
source tools/bench/peers/settled_bed.sh
start=10  # steps in the short run: the start-up
run() {  # threads steps
  local tag=$1.$2; rm -rf "$work/out.$tag" "$work/cg.$tag"-*
  settled_bed "$bin" "$2"
  OMP_WAIT_POLICY=passive valgrind --tool=callgrind --separate-threads=yes \
    --callgrind-out-file="$work/cg.$tag" "$bin" run "$scene" --resume "$state/settled.bin" \
    --out "$work/out.$tag" --force --until "$until" --threads "$1" --fixed-threads > "$work/log.$tag" 2>&1
  grep 'steps in' "$work/log.$tag"
}
for th in 1 2; do run $th $start; run $th $((start + steps)); done
python3 tools/bench/pour/regions.py "$work/cg.1.$start" "$work/cg.1.$((start + steps))" \
  "$work/cg.2.$start" "$work/cg.2.$((start + steps))"
