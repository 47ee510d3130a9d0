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
# SCENE=pile: the settled cubes of tools/bench/cubes.yaml tiled N_SIDE x N_SIDE (tile_pile.py: 3,375
# N_SIDE^2 cubes, resumed from its tiled checkpoint at rest) against the pile itself (N_SIDE 1),
# WINDOW 2e6 as cubes; PILE: the pile's checkpoint (default build/bench/cubes/settled.bin); rows
# in results_pile.csv.
# usage: [COMMIT=label] [SHAPE=cube | SCENE=pile] [WINDOW=particle-steps] tools/bench/scale/run_scale.sh [POLYDEM] [STEPS] [ROUNDS] [N_SIDE ...]
#        (defaults: build/polydem 200 3 30 60 100; 15 is the reference size, 1 the pile's)
set -euo pipefail
cd "$(dirname "$0")/../../.."
bin=$(realpath "${1:-build/polydem}")
steps=${2:-200}
rounds=${3:-3}
shift 3 || shift $#
sides=("${@:-30 60 100}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
pile=${SCENE:-} pile_checkpoint=$(realpath -m "${PILE:-build/bench/cubes/settled.bin}")
[ -z "$pile" ] || [ "$pile" = pile ] || { echo "run_scale.sh: SCENE must be pile (got $pile)" >&2; exit 1; }
[ -z "$pile" ] || SHAPE=pile
reference=$([ -n "$pile" ] && echo 1 || echo 15)  # N_SIDE each size is measured against
export SHAPE=${SHAPE:-sphere} REST=${REST:-$([ "${SHAPE:-}" = cube ] && echo 1 || echo 0)}  # read by scene.py
window=${WINDOW:-$([ "$SHAPE" = sphere ] && echo 34000000 || echo 2000000)}  # particle-steps timed a size, at least
csv=tools/bench/scale/results$([ "$SHAPE" = sphere ] || echo "_$SHAPE").csv
[ -s "$csv" ] || echo "commit,bodies,steps,round,us_per_particle_step,us_3375,ratio,peak_kB,kB_per_body" > "$csv"
commit=${COMMIT:-$(git rev-parse --short HEAD)}$([ "$REST" = 1 ] && [ -z "$pile" ] && echo -rest || true)  # COMMIT: the label of another build

bodies_of() {  # n -> the bodies of size n: n^3, or the pile's 3,375 n^2
  echo $([ -n "$pile" ] && echo $((3375 * $1 * $1)) || echo $(($1 * $1 * $1)))
}

cpu_seconds() {  # n steps -> user + system CPU seconds of one run of size n, and its peak RSS (kB)
  local n=$1 steps=$2 dt=5e-6 resume=()  # s, scene.py's step
  [ -z "$pile" ] || { dt=$(sed -n 's/.*dt: "\([^ ]*\) s".*/\1/p' "$work/scene_$n.yaml"); resume=(--resume "$work/tiled_$n.bin" --force); }
  rm -rf "$work/out"
  /usr/bin/time -v "$bin" run "$work/scene_$n.yaml" --out "$work/out" --threads 1 --fixed-threads \
      --until "$(python3 -c "print($steps * $dt)")" "${resume[@]}" > /dev/null 2> "$work/log" || { cat "$work/log"; exit 1; }
  local user sys peak
  user=$(grep 'User time' "$work/log" | awk '{print $NF}')
  sys=$(grep 'System time' "$work/log" | awk '{print $NF}')
  peak=$(grep 'Maximum resident' "$work/log" | awk '{print $NF}')
  echo "$(python3 -c "print($user + $sys)") $peak"
}

run_side() {  # n steps -> "us_per_particle_step peak_kB": the CPU time of `steps` more steps, per body-step
  local n=$1 steps=$2 short long peak
  if [ -n "$pile" ]; then
    [ -s "$work/scene_$n.yaml" ] || python3 tools/bench/scale/tile_pile.py "$n" "$pile_checkpoint" "$PWD/shapes/platonic.shp" \
        "$work/bodies_$n.csv" "$work/tiled_$n.bin" > "$work/scene_$n.yaml"
  else
    python3 tools/bench/scale/scene.py "$n" "$PWD/shapes/platonic.shp" lattice "$work/bodies_$n.csv" > "$work/scene_$n.yaml"
  fi
  read -r short _ <<< "$(cpu_seconds "$n" "$steps")"
  read -r long peak <<< "$(cpu_seconds "$n" $((2 * steps)))"
  echo "$(python3 -c "print(round(1e6 * ($long - $short) / ($steps * $(bodies_of "$n")), 4))") $peak"
}

steps_of() {  # n -> the steps of size n's window: STEPS, or more where WINDOW / bodies is more
  local b; b=$(bodies_of "$1")
  echo $(((window + b - 1) / b > steps ? (window + b - 1) / b : steps))
}

for n in ${sides[@]}; do
  for r in $(seq 1 "$rounds"); do
    read -r us_ref _ <<< "$(run_side "$reference" "$(steps_of "$reference")")"
    read -r us peak <<< "$(run_side "$n" "$(steps_of "$n")")"
    bodies=$(bodies_of "$n")
    row="$commit,$bodies,$(steps_of "$n"),$r,$us,$us_ref,$(python3 -c "print(round($us / $us_ref, 3))"),$peak,$(python3 -c "print(round($peak / $bodies, 3))")"
    echo "$row" | tee -a "$csv"
  done
done
