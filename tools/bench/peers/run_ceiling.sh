#!/usr/bin/env bash
# What two cores give here before any code's overheads (issues 19, 20): the settled bed's loop
# time of one 1-thread process alone, then of two such processes at once (nothing shared), then
# of `mpirun -np 2` with each rank's ghost waits (POLYDEM_MPI_TIMES), alternated ROUNDS times.
# ceiling = alone / (the slower of the two at once): the efficiency two independent copies
# reach, the most t1 / (2 t2) can be on this machine whatever the split.
# usage: [SCENE=cubes] tools/bench/peers/run_ceiling.sh POLYDEM [ROUNDS] [STEPS]   (5, 5000)
set -euo pipefail
cd "$(dirname "$0")/../../.."
bin=$1 rounds=${2:-5} steps=${3:-5000}
source tools/bench/peers/settled_bed.sh
settled_bed "$bin" "$steps"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
out=build/bench/ceiling
run() {  # output tag, then the launcher's words before the binary; prints the run's log
  rm -rf "$out/$1"
  local tag=$1; shift
  "$@" "$bin" run "$scene" --out "$out/$tag" --resume "$state/settled.bin" --force \
    --until "$until" --threads 1 --fixed-threads 2>&1
}
loop() { sed -n 's/.* steps in \([0-9.]*\) s.*/\1/p' | head -1; }
waits() { sed -n 's/.*ghost waits \([0-9.]*\) .*/\1/p' | sort -g | tr '\n' ' '; }
mkdir -p "$out"
for ((r = 0; r < rounds; ++r)); do
  alone=$(run alone env | loop)
  run a env > "$out/a.log" & run b env > "$out/b.log"; wait
  a=$(loop < "$out/a.log") b=$(loop < "$out/b.log")
  np2_log=$(run np2 mpirun -np 2 --bind-to none -x POLYDEM_MPI_TIMES=1)
  np2=$(loop <<< "$np2_log")
  ceiling=$(python3 -c "print(f'{$alone / max($a, $b):.3f}')")
  efficiency=$(python3 -c "print(f'{$alone / (2 * $np2):.3f}')")
  echo "alone $alone at_once $a $b ceiling $ceiling np2 $np2 efficiency $efficiency ghost_waits $(waits <<< "$np2_log")"
done
