#!/usr/bin/env bash
# Two builds alternated on a settled bed: each at 1 thread, 2 threads and `mpirun -np 2` (1 thread
# a rank), ROUNDS rounds of STEPS steps, printing polydem's own loop time (s, no start-up).
# Efficiency = t(1 thread) / (2 t(2)). SCENE=spheres (default): the peers' bed, made once by
# run_peers.sh; SCENE=cubes: tools/bench/cubes.yaml's settled pile, made once by run_bench.sh.
# A build before 27b641a spins as libgomp does by default: run both under GOMP_SPINCOUNT=1000.
# usage: [SCENE=cubes] tools/bench/peers/run_efficiency.sh NEW_POLYDEM OLD_POLYDEM [ROUNDS] [STEPS]   (5, 10000)
set -euo pipefail
cd "$(dirname "$0")/../../.."
new=$1 old=$2 rounds=${3:-5} steps=${4:-10000}
source tools/bench/peers/settled_bed.sh
settled_bed "$new" "$steps"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
out=build/bench/efficiency
loop_seconds() {  # launcher and binary (unquoted: words), threads
  rm -rf "$out"
  $1 run "$scene" --out "$out" --resume "$state/settled.bin" --force \
    --until "$until" --threads "$2" --fixed-threads 2>&1 | sed -n 's/.* steps in \([0-9.]*\) s.*/\1/p' | head -1
}
mpi="mpirun -np 2 --bind-to none"
for ((r = 0; r < rounds; ++r)); do
  echo "new_1t $(loop_seconds "$new" 1) old_1t $(loop_seconds "$old" 1) new_2t $(loop_seconds "$new" 2)" \
    "old_2t $(loop_seconds "$old" 2) new_np2 $(loop_seconds "$mpi $new" 1) old_np2 $(loop_seconds "$mpi $old" 1)"
done
