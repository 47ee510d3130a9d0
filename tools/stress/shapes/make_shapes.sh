#!/usr/bin/env bash
# Builds extreme.shp (needle 1:20, plate 20:1, ~2 cm, rounding 0.25 mm) from the point files here.
# usage: tools/stress/shapes/make_shapes.sh PATH/TO/polydem
set -euo pipefail
polydem=$(realpath "${1:?usage: make_shapes.sh PATH/TO/polydem}")
cd "$(dirname "$0")"
rm -f extreme.shp
for name in needle plate; do "$polydem" shape hull "$name.txt" --radius "0.25 mm" --name "$name" -o extreme.shp --append; done
"$polydem" shape info extreme.shp
