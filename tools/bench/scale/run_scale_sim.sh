#!/usr/bin/env bash
# Cost per particle-step from 3,375 to 10^6 spheres, counted rather than timed: callgrind with
# its cache simulation (L1 48 KB, LL 32 MB: this machine's L1d and L3) over the steps only
# (--toggle-collect on Simulation::step), a run of 2 STEPS less one of STEPS, at 1 thread. A
# load-independent stand-in for run_scale.sh's CPU times, which drift by 2x here when other
# jobs share the cores. Each size runs in the lattice's order and shuffled (scene.py): a pour
# leaves a body's neighbours anywhere in memory, which only the cache misses show.
# The estimate is cachegrind's: cycles = Ir + 10 (L1 misses) + 100 (LL misses).
# SHAPE=cube: scene.py's lattice of rounded cubes, face to face (rows in results_sim_cube.csv);
# ORDERS: the orders to count (default "lattice shuffled"). REST=1 (scene.py; cubes' default):
# the lattice at rest from the first step; its rows' order reads "lattice-rest". LL: the last
# level's bytes (default 33554432; 2097152: a core's L2 here), named in the order when not 32 MB.
# SCENE=pile: the settled cubes of tools/bench/cubes.yaml tiled N_SIDE x N_SIDE (tile_pile.py: 3,375
# N_SIDE^2 cubes, resumed from its tiled checkpoint at rest) instead of scene.py's lattice; PILE:
# the pile's checkpoint (default build/bench/cubes/settled.bin, run_bench.sh's); rows in
# results_sim_pile.csv, order "pile", with the two runs' list builds ("rebuilds": S and 2S runs').
# Prints and appends to tools/bench/scale/results_sim.csv:
# "commit,bodies,order,steps,ir,l1_miss,ll_miss,cycles_est,ratio" (per particle-step; ratio:
# the estimate against the same order's first size).
# usage: [SHAPE=cube | SCENE=pile] [ORDERS=lattice] tools/bench/scale/run_scale_sim.sh [POLYDEM] [N_SIDE:STEPS ...]
#        (defaults: build/polydem 15:20 30:10 60:4 100:2)
set -euo pipefail
cd "$(dirname "$0")/../../.."
bin=$(realpath "${1:-build/polydem}")
shift || true
sizes=("${@:-15:20 30:10 60:4 100:2}")
sizes=(${sizes[@]})
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
pile=${SCENE:-} pile_checkpoint=$(realpath -m "${PILE:-build/bench/cubes/settled.bin}")
[ -z "$pile" ] || [ "$pile" = pile ] || { echo "run_scale_sim.sh: SCENE must be pile (got $pile)" >&2; exit 1; }
[ -z "$pile" ] || { SHAPE=pile; ORDERS=pile; }
export SHAPE=${SHAPE:-sphere} REST=${REST:-$([ "${SHAPE:-}" = cube ] && echo 1 || echo 0)}  # read by scene.py
csv=tools/bench/scale/results_sim$([ "$SHAPE" = sphere ] || echo "_$SHAPE").csv
[ -s "$csv" ] || echo "commit,bodies,order,steps,ir,l1_miss,ll_miss,cycles_est,ratio$([ -z "$pile" ] || echo ,rebuilds)" > "$csv"
commit=${COMMIT:-$(git rev-parse --short HEAD)}
last_level=${LL:-33554432}  # bytes of the simulated last level

counts() {  # scene steps -> "Ir L1misses LLmisses rebuilds" of the steps
  rm -rf "$work/out"
  local dt=5e-6 resume=()  # s, scene.py's step
  [ -z "$pile" ] || { dt=$(sed -n 's/.*dt: "\([^ ]*\) s".*/\1/p' "$1"); resume=(--resume "$work/tiled.bin" --force); }
  valgrind --tool=callgrind --cache-sim=yes --D1=49152,12,64 --I1=32768,8,64 --LL="$last_level",16,64 \
      --collect-atstart=no --toggle-collect='polydem::Simulation::step()' --toggle-collect='polydem::Simulation::step(bool)' \
      --callgrind-out-file="$work/cg.out" "$bin" run "$1" --out "$work/out" --threads 1 \
      --fixed-threads --until "$(python3 -c "print($2 * $dt)")" "${resume[@]}" > "$work/stdout" 2> "$work/log" \
      || { cat "$work/log"; exit 1; }
  # events: Ir Dr Dw I1mr D1mr D1mw ILmr DLmr DLmw
  echo "$(awk '/^summary:/ {print $2, $5 + $6 + $7, $8 + $9 + $10}' "$work/cg.out")" \
      "$(sed -n 's/.* \([0-9]*\) rebuilds.*/\1/p' "$work/stdout" "$work/log")"
}

scene() {  # n -> the scene's file: scene.py's n^3 bodies, or the pile tiled n x n (its checkpoint beside)
  if [ -n "$pile" ]; then
    python3 tools/bench/scale/tile_pile.py "$1" "$pile_checkpoint" "$PWD/shapes/platonic.shp" "$work/bodies.csv" \
        "$work/tiled.bin" > "$work/scene.yaml"
  else
    python3 tools/bench/scale/scene.py "$1" "$PWD/shapes/platonic.shp" "$order" "$work/bodies.csv" > "$work/scene.yaml"
  fi
  echo "$work/scene.yaml"
}

for order in ${ORDERS:-lattice shuffled}; do
  first=""
  for size in "${sizes[@]}"; do
    n=${size%%:*} steps=${size##*:}
    file=$(scene "$n")
    read -r ir1 l11 ll1 rb1 <<< "$(counts "$file" "$steps")"
    read -r ir2 l12 ll2 rb2 <<< "$(counts "$file" $((2 * steps)))"
    bodies=$([ -n "$pile" ] && echo $((3375 * n * n)) || echo $((n * n * n)))
    row=$(python3 - "$bodies" "$steps" "$ir1" "$l11" "$ll1" "$ir2" "$l12" "$ll2" "${first:-0}" <<'EOF'
import sys
bodies, steps = int(sys.argv[1]), int(sys.argv[2])
a = [float(x) for x in sys.argv[3:9]]
per = [(a[3 + i] - a[i]) / (steps * bodies) for i in range(3)]
cycles = per[0] + 10 * per[1] + 100 * per[2]
first = float(sys.argv[9]) or cycles
print(f"{bodies},{steps},{per[0]:.1f},{per[1]:.2f},{per[2]:.3f},{cycles:.1f},{cycles / first:.3f}")
EOF
)
    [ -n "$first" ] || first=$(echo "$row" | cut -d, -f6)
    IFS=, read -r bodies st ir l1 ll cyc ratio <<< "$row"
    label=$order$([ "$REST" = 1 ] && [ -z "$pile" ] && echo -rest)$([ "$last_level" = 33554432 ] || echo "-ll$last_level")
    echo "$commit,$bodies,$label,$st,$ir,$l1,$ll,$cyc,$ratio$([ -z "$pile" ] || echo ",$rb1/$rb2")" | tee -a "$csv"
  done
done
