#!/usr/bin/env bash
# Fixed-state benchmark: settles each scene once (cached in build/bench/), then times STEPS
# steps from the settled checkpoint at 1 and 2 threads. Appends to tools/bench/results.csv:
# machine, commit, scene, threads, bodies, steps, seconds, us per particle-step, contacts, rebuilds;
# then prints each scene's 2-thread efficiency t1 / (2 t2) (issue 19 asks >= 0.9).
# usage: tools/bench/run_bench.sh [STEPS]   (STEPS for the settled scenes; the pour runs 0.2 s)
set -euo pipefail
cd "$(dirname "$0")/../.."
steps=${1:-2000}
bin=build/polydem
[ -x "$bin" ] || bash tools/build.sh
results=tools/bench/results.csv
[ -f "$results" ] || echo "machine,commit,scene,threads,bodies,steps,seconds,us_per_particle_step,contacts,rebuilds" > "$results"
machine=$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//; s/,//g')
declare -A seconds  # per scene and thread count, for the efficiency lines
for scene in cubes spheres; do
  settled=build/bench/$scene
  if [ ! -f "$settled/settled.bin" ]; then
    echo "settling $scene (once)..."
    "$bin" run tools/bench/$scene.yaml --out "$settled" --threads 2
    cp "$(ls "$settled"/checkpoint_*.bin | sort | tail -1)" "$settled/settled.bin"
  fi
  for threads in 1 2; do
    log=$(mktemp)
    dt_line=$("$bin" check tools/bench/$scene.yaml | grep 'chosen time step' | awk '{print $4}')
    t_settled=$(python3 - "$settled/energy.csv" <<'PY'
import sys
rows=[l.split(',') for l in open(sys.argv[1]).read().split('\n')[1:] if l]
print(rows[-1][0])
PY
)
    until=$(python3 -c "print($t_settled + $steps * $dt_line)")
    rm -rf "$settled/run$threads"  # a resumed run appends to its folder's series: start clean
    "$bin" run tools/bench/$scene.yaml --out "$settled/run$threads" --threads $threads --fixed-threads \
        --resume "$settled/settled.bin" --force --until "$until" 2> "$log"
    line=$(grep 'steps in' "$log")
    bodies=$(grep -m1 'bodies,' "$log" | sed 's/polydem: \([0-9]*\) bodies.*/\1/')
    nsteps=$(echo "$line" | sed 's/polydem: \([0-9]*\) steps.*/\1/')
    secs=$(echo "$line" | sed 's/.* steps in \([0-9.]*\) s.*/\1/')
    us=$(echo "$line" | sed 's/.*(\([0-9.e+-]*\) us per body-step).*/\1/')
    rebuilds=$(echo "$line" | sed 's/.*, \([0-9]*\) rebuilds.*/\1/')
    contacts=$(tail -1 "$settled/run$threads/energy.csv" | awk -F, '{print $8}')
    commit=$(git rev-parse --short HEAD)$(git diff --quiet HEAD -- src include || echo +)
    echo "\"$machine\",$commit,$scene,$threads,$bodies,$nsteps,$secs,$us,$contacts,$rebuilds" | tee -a "$results"
    seconds[$scene,$threads]=$secs
    rm -f "$log"
  done
done

# A pour: the box-fill sample's first 0.2 s (2,000 mixed polyhedra falling into a box, ~1,900
# rebuilds), where the neighbour-list rebuild and the feature candidates dominate.
for threads in 1 2; do
  log=$(mktemp)
  out=build/bench/pour$threads
  rm -rf "$out"
  "$bin" run samples/box-fill/scene.yaml --out "$out" --threads $threads --fixed-threads --until 0.2 2> "$log"
  line=$(grep 'steps in' "$log")
  nsteps=$(echo "$line" | sed 's/polydem: \([0-9]*\) steps.*/\1/')
  secs=$(echo "$line" | sed 's/.* steps in \([0-9.]*\) s.*/\1/')
  us=$(echo "$line" | sed 's/.*(\([0-9.e+-]*\) us per body-step).*/\1/')
  rebuilds=$(echo "$line" | sed 's/.*, \([0-9]*\) rebuilds.*/\1/')
  contacts=$(tail -1 "$out/energy.csv" | cut -d, -f8)
  commit=$(git rev-parse --short HEAD)$(git diff --quiet HEAD -- src include || echo +)
  echo "\"$machine\",$commit,pour,$threads,2000,$nsteps,$secs,$us,$contacts,$rebuilds" | tee -a "$results"
  seconds[pour,$threads]=$secs
  rm -f "$log"
done
for scene in cubes spheres pour; do
  python3 -c "print('efficiency $scene t1/(2 t2) = %.2f' % (${seconds[$scene,1]} / (2 * ${seconds[$scene,2]})))"
done
