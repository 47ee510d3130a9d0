#!/usr/bin/env bash
# Configures and builds build-asan/: clang, AddressSanitizer + UndefinedBehaviorSanitizer,
# RelWithDebInfo with line tables only (enough for the reports' stacks, a faster build). Used by
# tools/sanitize.sh. With --fuzz: build-fuzz/, the same plus libFuzzer's coverage instrumentation
# on every file and the fuzz_NAME targets (tools/fuzz.sh); the tests do not pay for it.
# usage: tools/build_asan.sh [--fuzz] [TARGET...]   (default: everything)
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh clang
command -v ccache > /dev/null && export CMAKE_CXX_COMPILER_LAUNCHER=${CMAKE_CXX_COMPILER_LAUNCHER:-ccache}
dir=build-asan fuzz=OFF
if [ "${1:-}" = --fuzz ]; then dir=build-fuzz fuzz=ON; shift; fi
mkdir -p "$dir"
CXX=clang++ cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -gline-tables-only -DNDEBUG" \
  -DPOLYDEM_SANITIZE=address,undefined -DPOLYDEM_FUZZ=$fuzz -DPOLYDEM_TEST_TIMEOUT=900 > "$dir/cmake.log" 2>&1 ||
  { cat "$dir/cmake.log"; exit 1; }
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build "$dir" -j"$(nproc)" "${targets[@]}" > "$dir/build.log" 2>&1 || { tail -50 "$dir/build.log"; exit 1; }
