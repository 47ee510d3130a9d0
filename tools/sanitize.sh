#!/usr/bin/env bash
# Builds polydem and its tests under AddressSanitizer and UndefinedBehaviorSanitizer (clang,
# RelWithDebInfo, build-asan/: tools/build_asan.sh) and runs every test but the two slowest.
# usage: tools/sanitize.sh [CTEST ARGS...]
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build_asan.sh
# Release runs these (5-45 s there, minutes under ASan); faster tests cover their code (the
# 4,500 spheres cover the threaded loops under ASan; the cubes timed out at 900 s on a loaded VM).
slow='energy budget: (the tangential dashpot|mixed polyhedra)|4,500 cubes'
cd build-asan
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --output-on-failure -j"$(nproc)" -E "$slow" "$@"
