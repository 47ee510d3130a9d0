#!/usr/bin/env bash
# tools/bench/scale/tile_pile.py reads a checkpoint and writes a tiled one polydem resumes: one
# tile resumes to the pile's own state, bit for bit (bodies, contacts, springs); 2 x 2 tiles hold
# four copies of each body and contact, the inner walls' contacts made again on the seams' mesh.
# usage: tile_pile.sh PATH/TO/polydem
set -euo pipefail
source "$(dirname "$0")/script_lib.bash" "$1"
tool="$here/../../tools/bench/scale/tile_pile.py"
# A small pile: 60 of cubes.yaml's cubes dropped in a corner of its box, in a heap by 0.2 s.
sed -e "s|\.\./\.\./shapes|$here/../../shapes|" -e 's/count: 3375/count: 60/' \
    -e 's/max: \[0.079, 0.079, 0.75\]/max: [-0.01, -0.01, 0.12]/' -e 's/duration: "0.8 s"/duration: "0.2 s"/' \
    -e 's/checkpoint_every: "0.1 s"/checkpoint_every: "1 s"/' "$here/../../tools/bench/cubes.yaml" > "$tmp/pile.yaml"
"$polydem" run "$tmp/pile.yaml" --out "$tmp/pile" --threads 1 > "$tmp/pile.log" 2>&1 || { cat "$tmp/pile.log"; fail "the pile's run"; }
pile=$(ls "$tmp"/pile/checkpoint_*.bin | sort | tail -1)
steps=$(basename "$pile" .bin | sed 's/checkpoint_0*//')
dt=$(python3 -c "import struct; print(repr(struct.unpack_from('<qd', open('$pile', 'rb').read(), 40 + 8 + 4 * 60)[1]))")
until_after() { python3 -c "print($1 * $dt)"; }  # s: step $1's time (the run rounds it to a step)

# One tile: its checkpoint at step 0 runs on as the pile's from its step, to the same state.
python3 "$tool" 1 "$pile" "$here/../../shapes/platonic.shp" "$tmp/b1.csv" "$tmp/t1.bin" > "$tmp/t1.yaml"
"$polydem" run "$tmp/pile.yaml" --resume "$pile" --out "$tmp/a" --threads 1 --until "$(until_after $((steps + 300)))" \
    > "$tmp/a.log" 2>&1 || { cat "$tmp/a.log"; fail "the pile's resume"; }
"$polydem" run "$tmp/t1.yaml" --resume "$tmp/t1.bin" --force --out "$tmp/b" --threads 1 --until "$(until_after 300)" \
    > "$tmp/b.log" 2>&1 || { cat "$tmp/b.log"; fail "one tile's resume"; }
PYTHONPATH="$(dirname "$tool")" python3 - "$tool" "$tmp"/a/checkpoint_*.bin "$tmp"/b/checkpoint_*.bin <<'EOF' || fail "one tile ends on other bits than the pile"
import sys
import tile_pile as tile
a, b = tile.read_pile(sys.argv[2]), tile.read_pile(sys.argv[3])
assert a["body_contacts"][0], "the pile has no contacts between bodies"
for key in ("ids", "state", "driver_fields"):
    assert a[key] == b[key], key
for key in ("body_contacts", "driver_contacts"):  # records and pairs; not the pending energies, which
    assert a[key][:2] == b[key][:2], key            # the two scenes' CSV rows (other times) close
EOF

# Two by two: four copies of every body; every contact a body has with a body comes back four
# times, and the seams' mesh (6 drivers) holds the cubes the inner walls held.
python3 "$tool" 2 "$pile" "$here/../../shapes/platonic.shp" "$tmp/b2.csv" "$tmp/t2.bin" > "$tmp/t2.yaml"
"$polydem" run "$tmp/t2.yaml" --resume "$tmp/t2.bin" --force --out "$tmp/c" --threads 1 --until "$(until_after 300)" \
    > "$tmp/c.log" 2>&1 || { cat "$tmp/c.log"; fail "2 x 2 tiles' resume"; }
PYTHONPATH="$(dirname "$tool")" python3 - "$tool" "$tmp"/b/checkpoint_*.bin "$tmp"/c/checkpoint_*.bin <<'EOF' || fail "2 x 2 tiles are not four piles"
import struct, sys
import tile_pile as tile
one, four = tile.read_pile(sys.argv[2]), tile.read_pile(sys.argv[3])
count = lambda p, which: len(p[which][0]) // tile.kContactBytes
assert len(four["ids"]) == 4 * len(one["ids"]) and four["drivers"] == 6, (len(four["ids"]), four["drivers"])
assert count(four, "body_contacts") == 4 * count(one, "body_contacts"), (count(four, "body_contacts"), count(one, "body_contacts"))
walls = lambda p: sum(1 for k in range(0, len(p["driver_contacts"][0]), tile.kContactBytes)
                      if struct.unpack_from("<I", p["driver_contacts"][0], k + 4)[0] != 0)
assert walls(four) == 4 * walls(one), (walls(four), walls(one))  # outer walls and seams: the piles' side walls
EOF
