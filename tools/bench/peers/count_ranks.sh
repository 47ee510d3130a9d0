#!/usr/bin/env bash
# What NP ranks do beyond one process on a settled bed, counted (issue 20): callgrind over whole
# processes (--toggle-collect is not reliable across MPI), one process and `mpirun -np NP` (1
# thread a rank), each a run of STEPS and one of 2 STEPS steps from the bed's settled state, so
# long less short is STEPS steps without start-up. rank_counts.py keeps the polydem binary's own
# functions and prints each rank, the sum, one process, efficiency = one process / (NP x slower
# rank) and the functions the ranks add most. SCENE as settled_bed.sh (spheres: the peers' bed,
# the default; cubes). Counted, not timed: the same under any load. Then the same totals over
# every object's functions (rank_counts.py with ALL=1: MPI's and libc's too, so a polling wait shows).
# usage: [SCENE=cubes] tools/bench/peers/count_ranks.sh BIN [STEPS=100] [NP=2] [WORKDIR=/tmp/rank_count]
set -euo pipefail
cd "$(dirname "$0")/../../.."
bin=$(realpath "$1"); steps=${2:-100}; np=${3:-2}
work=${4:-/tmp/rank_count}; mkdir -p "$work"
source tools/bench/peers/settled_bed.sh
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_WAIT_POLICY=passive
run() {  # launcher (words, empty: one process), tag, steps, file suffix
  local out="$work/out.$2.$3"; rm -rf "$out" "$work/cg.$2.$3".*
  settled_bed "$bin" "$3"
  $1 valgrind --tool=callgrind --callgrind-out-file="$work/cg.$2.$3.$4" \
    "$bin" run "$scene" --resume "$state/settled.bin" --out "$out" --force --until "$until" \
    --threads 1 --fixed-threads > "$work/log.$2.$3" 2>&1
  grep -m1 'steps in' "$work/log.$2.$3"
}
for s in "$steps" $((2 * steps)); do
  run "" one "$s" 0
  run "mpirun -np $np --bind-to none" "np$np" "$s" "%q{OMPI_COMM_WORLD_RANK}"
done
python3 tools/bench/peers/rank_counts.py "$work/cg.one.$steps.0" "$work/cg.one.$((2 * steps)).0" \
  "$work/cg.np$np.$steps" "$work/cg.np$np.$((2 * steps))"
echo; echo "every object (MPI and libc too):"
ALL=1 python3 tools/bench/peers/rank_counts.py "$work/cg.one.$steps.0" "$work/cg.one.$((2 * steps)).0" \
  "$work/cg.np$np.$steps" "$work/cg.np$np.$((2 * steps))" 0 | sed -n "1,$((np + 2))p"
