#!/usr/bin/env bash
# Which cache lines cross the two cores on the pour or a settled bed (issue 19): builds polydem with
# -DPOLYDEM_LINE_AUDIT=ON into build_audit/ (every access through line_audit.cpp's hooks; a folder
# of its own, never the Release build), runs STEPS steps of the box-fill pour from its 0.1 s state
# (SCENE=spheres: the peers' sphere bed from its settled state, settled_bed.sh) at 2 threads and
# prints, per stage of the step and array, the lines a step each thread touches, fetches from the
# other core and writes while the other holds them, and the lines both threads
# share between two barriers. Counted, not timed: the same on a loaded machine.
# usage: [SCENE=spheres] tools/bench/regions/line_audit.sh [STEPS=200] [OUT=/tmp/line_audit.txt] [STATE] [WORKDIR=/tmp/line_audit]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../.." && pwd)
steps=${1:-200} out=${2:-/tmp/line_audit.txt} work=${4:-/tmp/line_audit}
mkdir -p "$work"
command -v ccache > /dev/null && export CMAKE_CXX_COMPILER_LAUNCHER=${CMAKE_CXX_COMPILER_LAUNCHER:-ccache}
cmake -S "$root" -B "$root/build_audit" -DCMAKE_BUILD_TYPE=Release -DPOLYDEM_LINE_AUDIT=ON -DPOLYDEM_MPI=OFF > "$work/cmake.log"
cmake --build "$root/build_audit" -j"$(nproc)" --target polydem > "$work/build.log" 2>&1 || { tail -30 "$work/build.log"; exit 1; }
bin="$root/build_audit/polydem"
rm -rf "$work/out"
if [ "${SCENE:-pour}" = spheres ]; then  # the bed in build/bench/peers/polydem (STATE not read)
  cd "$root"; source tools/bench/peers/settled_bed.sh
  settled_bed "$root/build/polydem" "$steps"
  POLYDEM_LINE_AUDIT_OUT="$out" OMP_WAIT_POLICY=passive "$bin" run "$scene" --resume "$state/settled.bin" --out "$work/out" \
    --force --until "$until" --threads 2 --fixed-threads | grep 'steps in'
  cat "$out"
  exit 0
fi
source "$root/tools/bench/pour/state.sh"
state=${3:-$(pour_state "$root/build/polydem" "$work")}  # the state from the Release build (the audited one is slow)
pour_yaml "$work"
t0=0.1  # s, the state's time
POLYDEM_LINE_AUDIT_OUT="$out" OMP_WAIT_POLICY=passive "$bin" run "$work/pour.yaml" --resume "$state" --out "$work/out" \
  --force --until "$(python3 -c "print($t0 + ($steps + 0.5) * $pour_dt)")" --threads 2 --fixed-threads | grep 'steps in'
cat "$out"
