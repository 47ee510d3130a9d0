#!/usr/bin/env bash
# ThreadSanitizer on the threaded loops: builds tests_sim and tests_integrate with clang
# -fsanitize=thread and LLVM's OpenMP (libomp) in build-tsan/, and runs the tests that step
# scenes at 2 and 3 threads above every parallel threshold. libomp itself is not instrumented:
# Archer (libarcher.so, shipped with Debian's libomp) tells TSan about OpenMP's barriers and
# locks through OMPT, without which TSan reports races inside libomp. GCC's libgomp cannot
# be used so: it has neither OMPT nor TSan annotations.
# usage: tools/tsan.sh [CATCH2 FILTER]   (default: [threads],[determinism])
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh clang
archer=$(ls /usr/lib/llvm-*/lib/libarcher.so | sort -V | tail -1)
command -v ccache > /dev/null && export CMAKE_CXX_COMPILER_LAUNCHER=${CMAKE_CXX_COMPILER_LAUNCHER:-ccache}
mkdir -p build-tsan
CXX=clang++ cmake -S . -B build-tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPOLYDEM_SANITIZE=thread \
  > build-tsan/cmake.log 2>&1 || { cat build-tsan/cmake.log; exit 1; }
cmake --build build-tsan -j"${JOBS:-$(nproc)}" --target tests_sim tests_integrate > build-tsan/build.log 2>&1 ||
  { tail -50 build-tsan/build.log; exit 1; }
filter="${1:-[threads],[determinism]}"
# ignore_noninstrumented_modules: libomp is not instrumented; Archer reports its synchronisation.
export OMP_TOOL_LIBRARIES="$archer" TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1 ignore_noninstrumented_modules=1"
build-tsan/tests_sim "$filter"
build-tsan/tests_integrate "1 and 2 threads give bitwise identical states"
echo "tsan: no data race in the threaded loops ($filter)"
