#!/usr/bin/env bash
# Cost per particle-step and peak memory per body from 3,375 to 10^6 spheres: a simple cubic
# lattice of N = n^3 touching spheres (r = 5 mm, the bed's material) resting on a floor between
# four walls (3 contacts a sphere, a settled bed's count), STEPS steps at 1 thread under
# /usr/bin/time -v. The cost is CPU time (user + system: a machine shared with other jobs
# lends its cores, not its wall clock) of STEPS more steps, a run of 2 STEPS less one of STEPS:
# set-up and the first list build cancel. Each size is measured right after 3,375 spheres
# (ROUNDS pairs, alternated: the machine's speed drifts) and stated as the ratio of the pair's
# costs. Each size runs max(STEPS, WINDOW / N) steps (WINDOW, particle-steps: 3.4e7 for spheres,
# ~2 s of CPU at 0.06 us a sphere-step, 10,075 steps at 3,375; 2e6 for cubes, ~2-3 s), so each
# difference is seconds of CPU, not the 10 ms that /usr/bin/time resolves. Peak memory is the
# longer run's. Prints and appends to tools/bench/scale/results.csv: "commit,bodies,steps,round,
# us_per_particle_step,us_3375,ratio,peak_kB,kB_per_body" (steps: the size's).
# SHAPE=cube: scene.py's lattice of rounded cubes, face to face, against 3,375 of them (rows in
# results_cube.csv), at rest from the first step (scene.py's REST=1, its default for cubes;
# REST=1 for spheres too: a rested run's commit reads "abc1234-rest").
# usage: [COMMIT=label] [SHAPE=cube] [WINDOW=particle-steps] tools/bench/scale/run_scale.sh [POLYDEM] [STEPS] [ROUNDS] [N_SIDE ...]
#        (defaults: build/polydem 200 3 30 60 100; 15 is the reference size)
set -euo pipefail
cd "$(dirname "$0")/../../.."
bin=$(realpath "${1:-build/polydem}")
steps=${2:-200}
rounds=${3:-3}
shift 3 || shift $#
sides=("${@:-30 60 100}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export SHAPE=${SHAPE:-sphere} REST=${REST:-$([ "${SHAPE:-}" = cube ] && echo 1 || echo 0)}  # read by scene.py
window=${WINDOW:-$([ "$SHAPE" = cube ] && echo 2000000 || echo 34000000)}  # particle-steps timed a size, at least
csv=tools/bench/scale/results$([ "$SHAPE" = sphere ] || echo "_$SHAPE").csv
[ -s "$csv" ] || echo "commit,bodies,steps,round,us_per_particle_step,us_3375,ratio,peak_kB,kB_per_body" > "$csv"
commit=${COMMIT:-$(git rev-parse --short HEAD)}$([ "$REST" = 1 ] && echo -rest)  # COMMIT: the label of another build

cpu_seconds() {  # n steps -> user + system CPU seconds of one run of n^3 spheres, and its peak RSS (kB)
  local n=$1 steps=$2
  rm -rf "$work/out"
  /usr/bin/time -v "$bin" run "$work/scene_$n.yaml" --out "$work/out" --threads 1 --fixed-threads \
      --until "$(python3 -c "print($steps * 5e-6)")" > /dev/null 2> "$work/log" || { cat "$work/log"; exit 1; }
  local user sys peak
  user=$(grep 'User time' "$work/log" | awk '{print $NF}')
  sys=$(grep 'System time' "$work/log" | awk '{print $NF}')
  peak=$(grep 'Maximum resident' "$work/log" | awk '{print $NF}')
  echo "$(python3 -c "print($user + $sys)") $peak"
}

run_side() {  # n steps -> "us_per_particle_step peak_kB": the CPU time of `steps` more steps, per body-step
  local n=$1 steps=$2 short long peak
  python3 tools/bench/scale/scene.py "$n" "$PWD/shapes/platonic.shp" lattice "$work/bodies_$n.csv" > "$work/scene_$n.yaml"
  read -r short _ <<< "$(cpu_seconds "$n" "$steps")"
  read -r long peak <<< "$(cpu_seconds "$n" $((2 * steps)))"
  echo "$(python3 -c "print(round(1e6 * ($long - $short) / ($steps * $n ** 3), 4))") $peak"
}

steps_of() {  # n -> the steps of n^3 bodies' window: STEPS, or more where WINDOW / n^3 is more
  echo $(((window + $1 ** 3 - 1) / $1 ** 3 > steps ? (window + $1 ** 3 - 1) / $1 ** 3 : steps))
}

for n in ${sides[@]}; do
  for r in $(seq 1 "$rounds"); do
    read -r us_ref _ <<< "$(run_side 15 "$(steps_of 15)")"
    read -r us peak <<< "$(run_side "$n" "$(steps_of "$n")")"
    bodies=$((n * n * n))
    row="$commit,$bodies,$(steps_of "$n"),$r,$us,$us_ref,$(python3 -c "print(round($us / $us_ref, 3))"),$peak,$(python3 -c "print(round($peak / $bodies, 3))")"
    echo "$row" | tee -a "$csv"
  done
done
