#!/usr/bin/env bash
# Fingerprints of the final state of a fixed set of runs, for refactors that must keep the
# bits: every sample (part of its run), the bench pours and two scenes that use every law part
# and driver kind. Prints "run sha256(final checkpoint) sha256(energy.csv)"; diff two outputs.
# A format-06 checkpoint is hashed as the format-05 file of the same state (its payload between
# the 40-byte header and the 8-byte checksum), so runs before and after format 06 compare.
# usage: tools/bits/run_bits.sh [POLYDEM] [THREADS] > bits.txt   (about 2 minutes on 2 cores)
set -euo pipefail
cd "$(dirname "$0")/../.."
bin=$(realpath "${1:-build/polydem}")
threads=${2:-2}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
as_format05() {  # the checkpoint's bytes, format 06 written as format 05
  if [ "$(head -c 8 "$1")" = PDCKPT06 ]; then printf PDCKPT05; tail -c +41 "$1" | head -c -8; else cat "$1"; fi
}
run() {  # name scene until
  "$bin" run "$2" --out "$out/$1" --threads "$threads" --until "$3" > /dev/null 2>&1
  local last
  last=$(ls "$out/$1"/checkpoint_*.bin | sort | tail -1)
  echo "$1 $(as_format05 "$last" | sha256sum | cut -c1-16) $(sha256sum < "$out/$1/energy.csv" | cut -c1-16)"
}
run box-fill samples/box-fill/scene.yaml 0.25
run drum samples/drum/scene.yaml 0.5
run hopper samples/hopper/scene.yaml 0.3
run impact samples/impact/scene.yaml 0.3
run settling samples/settling/scene.yaml 1.5
run silo samples/silo/scene.yaml 0.3
run cubes tools/bench/cubes.yaml 0.06
run spheres tools/bench/spheres.yaml 0.15
run laws tools/bits/laws.yaml 0.3
run spheres_laws tools/bits/spheres_laws.yaml 0.3
