#!/usr/bin/env bash
# Fingerprints of the final state of a fixed set of runs, for refactors that must keep the
# bits: every sample (part of its run), the bench pours and two scenes that use every law part
# and driver kind. Prints "run sha256(final checkpoint) sha256(energy.csv)"; diff two outputs.
# A format-06 or 07 checkpoint is hashed as the format-05 file of the same state (its payload
# between the 40-byte header and the 8-byte checksum, 07 less the ledger's open sums:
# as_format05.py), so runs before and after formats 06 and 07 compare.
# `ledger-free`: both hashes leave the energy ledger out (the checkpoint's 72 ledger
# bytes after its step and dt, energy.csv's columns dissipated and its shares), to compare the state
# of builds whose ledgers round differently (the exact sum's closes).
# BODY_ORDER=input (or space) passes --body-order to every run: `input` keeps the bits of builds
# before body orders (sim/body_order.hpp), whose runs stored the bodies as the scenes list them.
# usage: [BODY_ORDER=input] tools/bits/run_bits.sh [POLYDEM] [THREADS] [ledger-free] > bits.txt
#        (about 2 minutes on 2 cores)
set -euo pipefail
cd "$(dirname "$0")/../.."
bin=$(realpath "${1:-build/polydem}")
threads=${2:-2}
ledger_free=${3:-}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
as_format05() { python3 tools/bits/as_format05.py "$1"; }  # formats 06 and 07 written as format 05
without_ledger() {  # the checkpoint ($1) or energy.csv (stdin) as hashed: ledger-free leaves the ledger out
  if [ -n "${1:-}" ]; then
    if [ -n "$ledger_free" ]; then as_format05 "$1" | { head -c 24; tail -c +97; }; else as_format05 "$1"; fi
  elif [ -n "$ledger_free" ]; then cut -d, -f1-4,6-12
  else cat; fi
}
run() {  # name scene until
  "$bin" run "$2" --out "$out/$1" --threads "$threads" --until "$3" ${BODY_ORDER:+--body-order "$BODY_ORDER"} \
      > /dev/null 2>&1
  local last
  last=$(ls "$out/$1"/checkpoint_*.bin | sort | tail -1)
  echo "$1 $(without_ledger "$last" | sha256sum | cut -c1-16) $(without_ledger < "$out/$1/energy.csv" | sha256sum | cut -c1-16)"
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
