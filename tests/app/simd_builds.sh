#!/usr/bin/env bash
# The AVX builds of the hot loops (feature kernels, pair walks, trailing passes, driver blocks) give
# the SSE2 builds' bits: a cube pile, a sphere bed and a scene with every law part, at 2 threads,
# run with the builds the CPU allows and with POLYDEM_SSE2 set, end in the same checkpoint and CSVs.
# usage: simd_builds.sh PATH/TO/polydem
set -euo pipefail
source "$(dirname "$0")/script_lib.bash" "$1"
root="$here/../.."
grep -qw avx /proc/cpuinfo && fast=AVX || fast=SSE2  # a CPU without AVX runs SSE2 both times
run() {  # name scene until out [env...]
  local name=$1 scene=$2 until=$3 out=$4; shift 4
  env "$@" "$polydem" run "$scene" --out "$tmp/$out/$name" --threads 2 --until "$until" 2> "$tmp/$out.$name.log" \
    || { cat "$tmp/$out.$name.log"; fail "$name ($out)"; }
}
# No function left out of line takes or returns a 256-bit vector by value: built for SSE2 it
# passes one in memory where an AVX caller uses a ymm register (clang under UBSan left
# lanes::gather out of line: the four-lane law's lanes 2 and 3 read garbage; lanes.hpp).
wide=$(nm -C --defined-only "$polydem" |
  grep -E '^[0-9a-f]+ [TtWw] ((double|long long) __vector\(4\) |.*[(,] ?(double|long long) __vector\(4\)[,)])' || true)
[ -z "$wide" ] || fail "out of line with a 256-bit vector by value: $(echo "$wide" | head -3 | cut -c1-200)"
for scene in "cubes $root/tools/bench/cubes.yaml 0.02" "spheres $root/tools/bench/spheres.yaml 0.05" \
             "laws $root/tools/bits/laws.yaml 0.1"; do
  set -- $scene
  run "$1" "$2" "$3" fast
  run "$1" "$2" "$3" sse2 POLYDEM_SSE2=1
  grep -q ", $fast kernels," "$tmp/fast.$1.log" || fail "$1: not the $fast build: $(head -1 "$tmp/fast.$1.log")"
  grep -q ", SSE2 kernels," "$tmp/sse2.$1.log" || fail "$1: POLYDEM_SSE2 not the SSE2 build"
  for f in "$tmp/fast/$1"/*.csv "$tmp/fast/$1"/checkpoint_*.bin; do
    cmp "$f" "$tmp/sse2/$1/$(basename "$f")" || fail "$1: $(basename "$f") differs between the $fast and SSE2 builds"
  done
done
echo "ok: $fast and SSE2 builds give the same bits; no out-of-line function passes a 256-bit vector"
