#!/usr/bin/env bash
# Builds polydem and runs one sample scene end to end: tools/run_sample.sh [SAMPLE] [polydem run options]
set -euo pipefail
cd "$(dirname "$0")/.."
sample=${1:-box-fill}
shift || true
bash tools/build.sh polydem
build/polydem run "samples/$sample/scene.yaml" "$@"
echo "ParaView: open samples/$sample/out/scene.pvd"
