#!/usr/bin/env bash
# Rebuilds the seed corpus of the fuzz targets (tests/fuzz/corpus/NAME) from the samples, the
# shape library, the tests' fixtures and checkpoints of checkpoint_scene.yaml.
# usage: tools/fuzz_corpus.sh [POLYDEM]   (default: build/polydem)
set -euo pipefail
here="$(cd "$(dirname "$0")/../tests/fuzz" && pwd)"
root="$here/../.."
polydem="${1:-$root/build/polydem}"
corpus="$here/corpus"
rm -rf "$corpus" && mkdir -p "$corpus"/{scene,body_table,shp,stl,vti,checkpoint}
for f in "$root"/samples/*/scene.yaml; do cp "$f" "$corpus/scene/$(basename "$(dirname "$f")").yaml"; done
cp "$root/tests/app/drop.yaml" "$corpus/scene/drop.yaml"
cp "$here/checkpoint_scene.yaml" "$corpus/scene/checkpoint_scene.yaml"
cp "$root"/shapes/*.shp "$corpus/shp/"
printf '%s\n' "# a table of every column" "shape, x, y, z, qw, qx, qy, qz, vx, vy, vz, wx, wy, wz, density, scale, group" \
  "cube, 0, 0, 0.1, 1, 0, 0, 0, 0, 0, -1, 0, 0, 0, 2700, 1, 0" "sphere, 0.02, 0, 0.1, 0.5, 0.5, 0.5, 0.5, 0, 0, 0, 1, 2, 3, 1500, 1.5, 2" \
  > "$corpus/body_table/all_columns.csv"
printf '%s\n' "shape,x,y,z" "octahedron,1e-3,-2.5e-2,+3" "tetra,0,0,0" > "$corpus/body_table/required.csv"
printf 'shape,x,y,z,density\r\ncube,0,0,0,2700\r\nrock,1,2,3,-1\r\n' > "$corpus/body_table/crlf_bad.csv"
cp "$root/samples/silo/meshes/plate_D50.stl" "$corpus/stl/"   # binary (the hopper: 300 kB, too big a seed)
cat > "$corpus/stl/tetra_ascii.stl" <<'STL'
solid t
facet normal 0 0 -1
outer loop
vertex 0 0 0
vertex 0 1 0
vertex 1 0 0
endloop
endfacet
facet normal 0 -1 0
outer loop
vertex 0 0 0
vertex 1 0 0
vertex 0 0 1
endloop
endfacet
facet normal -1 0 0
outer loop
vertex 0 0 0
vertex 0 0 1
vertex 0 1 0
endloop
endfacet
facet normal 1 1 1
outer loop
vertex 1 0 0
vertex 0 1 0
vertex 0 0 1
endloop
endfacet
endsolid t
STL
# The same tetrahedron in binary: 80-byte header, count, 50 bytes per triangle.
python3 - "$corpus/stl/tetra_binary.stl" <<'PY'
import struct, sys
tris = [((0,0,-1),(0,0,0),(0,1,0),(1,0,0)), ((0,-1,0),(0,0,0),(1,0,0),(0,0,1)),
        ((-1,0,0),(0,0,0),(0,0,1),(0,1,0)), ((1,1,1),(1,0,0),(0,1,0),(0,0,1))]
with open(sys.argv[1], "wb") as f:
    f.write(b"solid binary tetrahedron".ljust(80, b" ") + struct.pack("<I", len(tris)))
    for t in tris:
        f.write(struct.pack("<12fH", *[c for v in t for c in v], 0))
PY
python3 "$here/make_vti_seeds.py" "$corpus/vti"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$polydem" run "$here/checkpoint_scene.yaml" --out "$tmp/out" --threads 1 > /dev/null 2>&1
cp "$tmp"/out/checkpoint_*.bin "$corpus/checkpoint/"
echo "corpus: $(find "$corpus" -type f | wc -l) seeds in $corpus"
