#!/usr/bin/env bash
# Counted instructions of Simulation::step (callgrind, 1 thread) from a benchmark state (issue 19):
# the settled cubes 200 steps, the peers' sphere bed 300, the box-fill pour 200 from 0.1 s.
# usage: tools/bench/count_step.sh cubes|bed|pour BIN OUTFILE   (states: run_bench.sh, run_peers.sh)
# Prints: total Ir, and sha256 of the final checkpoint and energy.csv (first 16 hex each).
set -euo pipefail
what=$1; bin=$(realpath "$2"); out=$(realpath -m "$3")
cd "$(dirname "$0")/../.."
work=$(mktemp -d /tmp/count.XXXX); trap 'rm -rf "$work"' EXIT
case $what in
  cubes|bed)
    [ "$what" = cubes ] && export SCENE=cubes || export SCENE=spheres
    source tools/bench/peers/settled_bed.sh
    steps=200; [ "$what" = bed ] && steps=300
    settled_bed "$bin" $steps
    args=("$scene" --resume "$state/settled.bin" --force --until "$until") ;;
  pour)
    source tools/bench/pour/state.sh
    mkdir -p /tmp/pour45; st=$(pour_state "$bin" /tmp/pour45)
    args=(/tmp/pour45/pour.yaml --resume "$st" --force --until $(python3 -c "print(0.1 + 200 * $pour_dt)")) ;;
  *) echo "cubes|bed|pour" >&2; exit 1 ;;
esac
OMP_WAIT_POLICY=passive valgrind --tool=callgrind --collect-atstart=no \
  --toggle-collect='polydem::Simulation::step(bool)' --callgrind-out-file="$out" \
  "$bin" run "${args[@]}" --out "$work/o" --threads 1 --fixed-threads > "$work/log" 2>&1 || { cat "$work/log"; exit 1; }
ir=$(grep -m1 '^summary:' "$out" | awk '{print $2}')
ck=$(ls "$work"/o/checkpoint_*.bin | sort | tail -1)
echo "$what Ir $ir ck $(sha256sum "$ck" | cut -c1-16) energy $(sha256sum "$work/o/energy.csv" | cut -c1-16) ($(grep -c . "$work/o/energy.csv") rows)"
