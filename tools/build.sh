#!/usr/bin/env bash
# Installs the dependencies and builds polydem (Release) into build/.
# usage: tools/build.sh [TARGET...]   (default: everything, tests included)
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
# Rebuilds of a tree already compiled once (another worktree, a switched branch) hit the cache.
command -v ccache > /dev/null && export CMAKE_CXX_COMPILER_LAUNCHER=${CMAKE_CXX_COMPILER_LAUNCHER:-ccache}
mkdir -p build && cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > build/cmake.log 2>&1 || { cat build/cmake.log; exit 1; } 
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build build -j"$(nproc)" "${targets[@]}" > build/build.log 2>&1 || { tail -50 build/build.log; exit 1; }
echo "build: build/polydem"
