#!/usr/bin/env bash
# The threads' waits counted (issue 19): one callgrind run at 2 threads (passive waits) of STEPS steps
# from the pour's 0.1 s state (SCENE=pour, the default; tools/bench/pour/state.sh) or a settled bed
# (SCENE=spheres or cubes, tools/bench/peers/settled_bed.sh), the main thread's instructions dumped
# before and after each GOMP_parallel, before each step and after each rebuild; waits.py prints a step's
# regions, barriers and serial stretches (the work the other thread waits through), with and
# without a rebuild, and each rebuild's. Counted, not timed: the same under any load.
# usage: [SCENE=pour|spheres|cubes] tools/bench/regions/count_waits.sh BIN [STEPS=400] [WORKDIR=/tmp/waits]
set -euo pipefail
root=$(cd "$(dirname "$0")/../../.." && pwd)
bin=$(realpath "$1"); steps=${2:-400}
work=$(realpath -m "${3:-/tmp/waits}"); mkdir -p "$work"
skip=10  # steps left out: the start-up and its first rebuild
total=$((skip + steps + 1))  # the last step's dump closes the one before
cd "$root"
if [ "${SCENE:-pour}" = pour ]; then
  source tools/bench/pour/state.sh
  state=$(pour_state "$bin" "$work"); pour_yaml "$work"; scene=$work/pour.yaml
  until=$(python3 -c "print(0.1 + ($total + 0.5) * $pour_dt)")  # from the state's 0.1 s
else
  source tools/bench/peers/settled_bed.sh
  settled_bed "$bin" "$total"; state=$state/settled.bin
fi
rm -rf "$work/out" "$work/cg"; mkdir -p "$work/cg"
OMP_WAIT_POLICY=passive valgrind --tool=callgrind --separate-threads=yes \
  --toggle-collect='polydem::Simulation::step(bool)' --dump-before='polydem::Simulation::step(bool)' \
  --dump-before=GOMP_parallel --dump-after=GOMP_parallel \
  --dump-after='polydem::ContactEngine::rebuild(polydem::LocalBodies const&, polydem::Drivers const&, bool)' \
  --callgrind-out-file="$work/cg/cg" "$bin" run "$scene" --resume "$state" --out "$work/out" --force \
  --until "$until" --threads 2 --fixed-threads > "$work/log" 2>&1
grep 'steps in' "$work/log"
python3 tools/bench/regions/waits.py "$work/cg/cg" "$skip"
