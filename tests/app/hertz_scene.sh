#!/usr/bin/env bash
# A Hertz scene file end to end: a sphere (r 5 mm, platonic.shp) thrown at 1 m/s at a wall of
# another material (model: hertz, E and poisson with units), no gravity. `check` prints the
# Hertz stiffness dt: auto took; `run` ends with the sphere leaving at en x 1 m/s (kinetic
# energy en^2 of the start, within 0.1% on en at dt: auto, the step of accuracy 1e-3), and a bad
# poisson is refused at its line.
set -euo pipefail
source "$(dirname "$0")/script_lib.bash" "$1"
write_scene() {  # write_scene POISSON FILE
  cat > "$2" <<YAML
simulation: {duration: "2 ms", dt: auto}
shapes: [$here/../../shapes/platonic.shp]
bodies:
  - {shape: sphere, position: [0, 0, 0.0055], velocity: [0, 0, -1]}
drivers:
  - wall: {name: floor, point: [0, 0, 0], normal: [0, 0, 1]}
forces:
  - contact_polyhedron:
      config: {model: hertz, E: "70 GPa", poisson: $1, mu: 0.5, en: 0.6}
      config_driver: {model: hertz, E: "210 GPa", poisson: 0.3, mu: 0.3, en: 0.6}
output: {csv_every: "0.1 ms"}
YAML
}
write_scene 0.22 "$tmp/good.yaml"
write_scene 0.8 "$tmp/bad.yaml"
"$polydem" check "$tmp/good.yaml" > "$tmp/check.out" || fail "check of the Hertz scene"
grep -q "hertz: for an impact at 1 m/s" "$tmp/check.out" || { cat "$tmp/check.out"; fail "check: no Hertz stiffness line"; }
"$polydem" run "$tmp/good.yaml" --out "$tmp/good" --threads 1 > /dev/null 2> "$tmp/run.err" || { cat "$tmp/run.err"; fail "run"; }
python3 - "$tmp/good/energy.csv" <<'PY' || fail "restitution"
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
first, last = float(rows[0]["kinetic"]), float(rows[-1]["kinetic"])
en = math.sqrt(last / first)
print(f"hertz scene: en {en:.6f} for 0.6")
assert abs(en - 0.6) < 6e-4 and int(rows[-1]["contacts"]) == 0, en
PY
if "$polydem" check "$tmp/bad.yaml" > /dev/null 2> "$tmp/bad.err"; then fail "a poisson of 0.8 was accepted"; fi
grep -q "bad.yaml:9: key 'poisson': must be in \[0, 0.5\]" "$tmp/bad.err" || { cat "$tmp/bad.err"; fail "bad poisson: no file, line and key"; }
echo "hertz_scene: 1 passed, 0 failed"
