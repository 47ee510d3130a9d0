#!/usr/bin/env bash
# Rebuilds the shipped shape library (shapes/*.shp) from the point files in shapes/sources/.
# usage: tools/make_shapes.sh PATH/TO/polydem
set -euo pipefail
polydem=$(realpath "${1:?usage: tools/make_shapes.sh PATH/TO/polydem}")
cd "$(dirname "$0")/../shapes"

# hull LIBRARY NAME RADIUS: adds the hull of sources/NAME.txt to LIBRARY as shape NAME.
hull() { "$polydem" shape hull "sources/$2.txt" --radius "$3" --name "$2" -o "$1" --append; }

rm -f platonic.shp boxes.shp rocks.shp
hull platonic.shp sphere "5 mm"
for name in tetrahedron cube octahedron dodecahedron icosahedron; do hull platonic.shp "$name" "0.5 mm"; done
for name in box_elongated box_flat; do hull boxes.shp "$name" "0.5 mm"; done
for name in rock1 rock2 rock3; do hull rocks.shp "$name" "0.5 mm"; done
"$polydem" shape info platonic.shp
"$polydem" shape info boxes.shp
"$polydem" shape info rocks.shp
