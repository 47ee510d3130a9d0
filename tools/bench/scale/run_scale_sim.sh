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
# Prints and appends to tools/bench/scale/results_sim.csv:
# "commit,bodies,order,steps,ir,l1_miss,ll_miss,cycles_est,ratio" (per particle-step; ratio:
# the estimate against the same order's first size).
# usage: [SHAPE=cube] [ORDERS=lattice] tools/bench/scale/run_scale_sim.sh [POLYDEM] [N_SIDE:STEPS ...]
#        (defaults: build/polydem 15:20 30:10 60:4 100:2)
set -euo pipefail
cd "$(dirname "$0")/../../.."
bin=$(realpath "${1:-build/polydem}")
shift || true
sizes=("${@:-15:20 30:10 60:4 100:2}")
sizes=(${sizes[@]})
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export SHAPE=${SHAPE:-sphere} REST=${REST:-$([ "${SHAPE:-}" = cube ] && echo 1 || echo 0)}  # read by scene.py
csv=tools/bench/scale/results_sim$([ "$SHAPE" = sphere ] || echo "_$SHAPE").csv
[ -s "$csv" ] || echo "commit,bodies,order,steps,ir,l1_miss,ll_miss,cycles_est,ratio" > "$csv"
commit=${COMMIT:-$(git rev-parse --short HEAD)}
last_level=${LL:-33554432}  # bytes of the simulated last level

counts() {  # scene steps -> "Ir L1misses LLmisses" of the steps
  rm -rf "$work/out"
  valgrind --tool=callgrind --cache-sim=yes --D1=49152,12,64 --I1=32768,8,64 --LL="$last_level",16,64 \
      --collect-atstart=no --toggle-collect='polydem::Simulation::step()' --toggle-collect='polydem::Simulation::step(bool)' \
      --callgrind-out-file="$work/cg.out" "$bin" run "$1" --out "$work/out" --threads 1 \
      --fixed-threads --until "$(python3 -c "print($2 * 5e-6)")" > /dev/null 2> "$work/log" \
      || { cat "$work/log"; exit 1; }
  # events: Ir Dr Dw I1mr D1mr D1mw ILmr DLmr DLmw
  awk '/^summary:/ {print $2, $5 + $6 + $7, $8 + $9 + $10}' "$work/cg.out"
}

for order in ${ORDERS:-lattice shuffled}; do
  first=""
  for size in "${sizes[@]}"; do
    n=${size%%:*} steps=${size##*:}
    python3 tools/bench/scale/scene.py "$n" "$PWD/shapes/platonic.shp" "$order" "$work/bodies.csv" > "$work/scene.yaml"
    read -r ir1 l11 ll1 <<< "$(counts "$work/scene.yaml" "$steps")"
    read -r ir2 l12 ll2 <<< "$(counts "$work/scene.yaml" $((2 * steps)))"
    row=$(python3 - "$n" "$steps" "$ir1" "$l11" "$ll1" "$ir2" "$l12" "$ll2" "${first:-0}" <<'EOF'
import sys
n, steps = int(sys.argv[1]), int(sys.argv[2])
a = [float(x) for x in sys.argv[3:9]]
per = [(a[3 + i] - a[i]) / (steps * n ** 3) for i in range(3)]
cycles = per[0] + 10 * per[1] + 100 * per[2]
first = float(sys.argv[9]) or cycles
print(f"{n ** 3},{steps},{per[0]:.1f},{per[1]:.2f},{per[2]:.3f},{cycles:.1f},{cycles / first:.3f}")
EOF
)
    [ -n "$first" ] || first=$(echo "$row" | cut -d, -f6)
    IFS=, read -r bodies st ir l1 ll cyc ratio <<< "$row"
    echo "$commit,$bodies,$order$([ "$REST" = 1 ] && echo -rest)$([ "$last_level" = 33554432 ] || echo "-ll$last_level"),$st,$ir,$l1,$ll,$cyc,$ratio" | tee -a "$csv"
  done
done
