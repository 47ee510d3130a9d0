#!/usr/bin/env bash
# Builds polydem and its tests with clang under AddressSanitizer and UndefinedBehaviorSanitizer
# (RelWithDebInfo, in build-asan/) and runs the tests but the slowest (Release runs them).
# The same build holds the libFuzzer targets (tools/fuzz.sh), so fuzzing needs no second build.
# usage: tools/sanitize.sh [CTEST ARGS...]
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh clang
command -v ccache > /dev/null && export CMAKE_CXX_COMPILER_LAUNCHER=${CMAKE_CXX_COMPILER_LAUNCHER:-ccache}
mkdir -p build-asan
CXX=clang++ cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPOLYDEM_SANITIZE=address,undefined \
  -DPOLYDEM_FUZZ=ON -DPOLYDEM_TEST_TIMEOUT=900 > build-asan/cmake.log 2>&1 || { cat build-asan/cmake.log; exit 1; }
cmake --build build-asan -j"$(nproc)" > build-asan/build.log 2>&1 || { tail -50 build-asan/build.log; exit 1; }
# Release runs these (30-45 s there, minutes under ASan); their code paths run in faster tests too.
slow='energy budget: (the tangential dashpot|mixed polyhedra)'
cd build-asan
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --output-on-failure -j"$(nproc)" -E "$slow" "$@"
