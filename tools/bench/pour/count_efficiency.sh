#!/usr/bin/env bash
# Counted 2-thread efficiency of the pour (issue 19): callgrind at 1 and 2 threads from the box-fill
# sample's 0.1 s checkpoint, a run of START steps (start-up) and one of START + STEPS; regions.py
# takes long less short a thread and prints T1, the serial part, each region's two threads and
# T1 / (2 T2). Counted, not timed: valgrind runs the threads in turn, so it holds under any load.
# usage: tools/bench/pour/count_efficiency.sh BIN [STEPS=400] [STATE] [WORKDIR=/tmp/pour_eff]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
bin=$(realpath "$1"); steps=${2:-400}
state=${3:-/work/states/pour20/boxfill_t0.1.bin}
work=${4:-/tmp/pour_eff}; mkdir -p "$work"
start=10  # steps in the short run: the start-up and the first rebuild
dt=8.498501385433668e-06  # the sample's auto dt (polydem check samples/box-fill/scene.yaml)
t0=0.1  # the state's time
sed "s#\.\./\.\./shapes/#$here/../../../shapes/#; s#dt: auto#dt: $dt#" \
  "$here/../../../samples/box-fill/scene.yaml" > "$work/pour.yaml"
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
