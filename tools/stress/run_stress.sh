#!/usr/bin/env bash
# Stress tests: time-step sweep to blow-up, high-speed wall impacts, 10^6-step rest, extreme
# shapes and size mixes. One run at a time with --threads 1; rows go to tools/stress/results.csv.
# usage: tools/stress/run_stress.sh [BUILD_DIR] [dt[:sphere,cube,..]|impact|sheet|rest|extreme ...]
#   (all: ~6 min on one core, of which rest ~3 min; scenes and outputs in BUILD_DIR/stress/)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
shift || true
[ -x "$build/polydem" ] || bash tools/build.sh polydem
[ -f tools/stress/shapes/extreme.shp ] || bash tools/stress/shapes/make_shapes.sh "$build/polydem"
/usr/bin/python3 tools/stress/stress.py "$build/polydem" "$build/stress" "$@"
