#!/usr/bin/env bash
# Installs the dependencies, builds polydem and its tests, and runs every test through CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh
cd build
ctest --output-on-failure -j"$(nproc)"
