#!/usr/bin/env bash
# A body table (`- file: bodies.csv`) runs to the same final state, byte for byte, as the same
# bodies listed in YAML; a bad cell stops with the table's file, row and column and exit 1.
# usage: body_table.sh PATH/TO/polydem
set -euo pipefail
source "$(dirname "$0")/script_lib.bash" "$1"
# Mixed shapes with orientations, velocities, densities and groups, falling into the box.
rows=(
  "cube,0,0,0.006,0.9961946980917455,0,0,0.08715574274765817,0,0,0,0,0,0,2700,1,0"
  "sphere,0.012,-0.01,0.03,1,0,0,0,0.1,0,-1,0,0,5,1500,1.2,1"
  "octahedron,-0.015,0.01,0.05,0.5,0.5,0.5,0.5,0,0,-1,3,0,0,2700,0.8,2"
  "cube,0.002,0.004,0.08,0.7071067811865476,0.7071067811865475,0,0,0,-0.25,-0.5,0,1,0,2500,1,1"
)
{ echo "# shape, position, quaternion, velocity, angular velocity, density, scale, group"
  echo "shape, x, y, z, qw, qx, qy, qz, vx, vy, vz, wx, wy, wz, density, scale, group"
  printf '%s\n' "${rows[@]}"; } > "$tmp/bodies.csv"
yaml_bodies() {
  local s x y z qw qx qy qz vx vy vz wx wy wz d k g
  for r in "${rows[@]}"; do
    IFS=, read -r s x y z qw qx qy qz vx vy vz wx wy wz d k g <<< "$r"
    echo "  - {shape: $s, position: [$x, $y, $z], orientation: {quaternion: [$qw, $qx, $qy, $qz]},"
    echo "     velocity: [$vx, $vy, $vz], angular_velocity: [$wx, $wy, $wz], density: $d, scale: $k, group: $g}"
  done
}
scene() {  # scene BODIES_BLOCK: drop.yaml with its bodies replaced
  sed -e "s|\.\./\.\./shapes|$here/../../shapes|" -e '/^bodies:/,/^drivers:/{/^bodies:/!{/^drivers:/!d}}' \
      "$here/drop.yaml" | awk -v block="$1" '{print} /^bodies:/ {print block}'
}
scene "$(yaml_bodies)" > "$tmp/list.yaml"
scene "  - file: bodies.csv" > "$tmp/table.yaml"
"$polydem" run "$tmp/list.yaml" --out "$tmp/list" --threads 2 2> "$tmp/list.log" || { cat "$tmp/list.log"; fail "list run"; }
"$polydem" run "$tmp/table.yaml" --out "$tmp/table" --threads 2 2> "$tmp/table.log" || { cat "$tmp/table.log"; fail "table run"; }
final=$(cd "$tmp/list" && ls checkpoint_*.bin | sort | tail -1)
cmp "$tmp/list/$final" "$tmp/table/$final" || fail "the table's run ends on other bits than the list's"
cmp "$tmp/list/energy.csv" "$tmp/table/energy.csv" || fail "energy.csv differs"
grep -q "bodies: 4" <("$polydem" check "$tmp/table.yaml") || fail "check: not 4 bodies"

# A bad cell: the table's file, row and column, exit 1.
sed -i '5s/0.05,/0.05 m,/' "$tmp/bodies.csv"
expect_exit 1 "bodies.csv:5: key 'z': expected a finite number" "$polydem" run "$tmp/table.yaml" --out "$tmp/bad"
