#!/usr/bin/env bash
# Configures and builds build-asan/: clang, AddressSanitizer + UndefinedBehaviorSanitizer,
# RelWithDebInfo, with the libFuzzer targets. Used by tools/sanitize.sh and tools/fuzz.sh.
# usage: tools/build_asan.sh [TARGET...]   (default: everything)
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh clang
command -v ccache > /dev/null && export CMAKE_CXX_COMPILER_LAUNCHER=${CMAKE_CXX_COMPILER_LAUNCHER:-ccache}
mkdir -p build-asan
CXX=clang++ cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPOLYDEM_SANITIZE=address,undefined \
  -DPOLYDEM_FUZZ=ON -DPOLYDEM_TEST_TIMEOUT=900 > build-asan/cmake.log 2>&1 || { cat build-asan/cmake.log; exit 1; }
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build build-asan -j"$(nproc)" "${targets[@]}" > build-asan/build.log 2>&1 || { tail -50 build-asan/build.log; exit 1; }
