#!/usr/bin/env bash
# Installs the dependencies, builds polydem and its tests, and runs every test through CTest;
# then the same tests under AddressSanitizer and UndefinedBehaviorSanitizer (tools/sanitize.sh:
# clang, build-asan/), the fuzz corpus and saved crash inputs included (tests_fuzz).
# usage: tools/test.sh [--no-sanitizers]
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh
(cd build && ctest --output-on-failure -j"$(nproc)")
[ "${1:-}" = --no-sanitizers ] || bash tools/sanitize.sh
