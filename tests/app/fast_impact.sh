#!/usr/bin/env bash
# A sphere (r 5 mm, 1.41 g) thrown at a wall with kn = 1e5 N/m overlaps about v sqrt(m/kn)
# = 0.119 mm per m/s: half its radius at 21 m/s. At 200 m/s `check` and `run` must warn,
# naming the body, the driver and the speed limit; at 1 m/s they must not.
set -euo pipefail
source "$(dirname "$0")/script_lib.bash" "$1"
write_scene() {  # write_scene SPEED FILE
  cat > "$2" <<YAML
simulation: {duration: "0.5 ms", dt: auto}
shapes: [$here/../../shapes/platonic.shp]
bodies:
  - {shape: sphere, position: [0, 0, 0.02], velocity: [0, 0, -$1]}
drivers:
  - wall: {name: floor, point: [0, 0, 0], normal: [0, 0, 1]}
forces:
  - contact_polyhedron:
      config: {kn: 1.0e5, kt: 1.0e5, mu: 0.5, en: 0.5}
output: {csv_every: "0.1 ms"}
YAML
}
write_scene 200 "$tmp/fast.yaml"
write_scene 1 "$tmp/slow.yaml"
"$polydem" check "$tmp/fast.yaml" > "$tmp/check.out" 2> "$tmp/check.err" || fail "check of the fast scene"
grep -q "warning: body 0 (shape 'sphere') may hit driver 'floor' at 200 m/s: above 21 m/s" "$tmp/check.err" \
  || { cat "$tmp/check.err"; fail "check: no fast-impact warning naming body, driver and speed"; }
grep -q "use kn >= " "$tmp/check.err" || fail "check: no suggested kn"
"$polydem" run "$tmp/fast.yaml" --out "$tmp/fast" --threads 1 2> "$tmp/fast.err" > /dev/null || fail "run of the fast scene"
grep -q "may hit driver 'floor' at 200 m/s" "$tmp/fast.err" || { cat "$tmp/fast.err"; fail "run: no fast-impact warning"; }
grep -q "an overlap of" "$tmp/fast.err" || { cat "$tmp/fast.err"; fail "run: no warning when the overlap got too deep"; }
"$polydem" check "$tmp/slow.yaml" > /dev/null 2> "$tmp/slow_check.err" || fail "check of the slow scene"
"$polydem" run "$tmp/slow.yaml" --out "$tmp/slow" --threads 1 2> "$tmp/slow.err" > /dev/null || fail "run of the slow scene"
if grep -q "warning" "$tmp/slow_check.err" "$tmp/slow.err"; then cat "$tmp/slow_check.err" "$tmp/slow.err"; fail "warning at 1 m/s"; fi
echo "fast_impact: 1 passed, 0 failed"
