#!/usr/bin/env bash
# The first view of the box-fill sample: bodies.pvd, drivers.pvd and contacts.pvd beside
# scene.pvd, read back with VTK; the five walls meet at the box's edges and frame every body.
# usage: view_output.sh PATH/TO/polydem
set -euo pipefail
polydem=$1
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# The sample as it is but for a frame every 0.1 ms, so three frames take 20 steps.
sed 's|vtk_every: .*|vtk_every: "0.1 ms"|; s|\.\./\.\./shapes|'"$here"'/../../shapes|' \
  "$here/../../samples/box-fill/scene.yaml" > "$tmp/scene.yaml"
"$polydem" run "$tmp/scene.yaml" --until 0.00021 --out "$tmp/out" 2> "$tmp/log" ||
  { cat "$tmp/log"; exit 1; }
/usr/bin/python3 "$here/check_view.py" "$tmp/out"
