#!/usr/bin/env bash
# driver_NAME.csv against the forces: a 5 mm sphere on a floor under gravity, pressed by a ball
# servo of 0.05 N. At rest the floor carries m g + F (fz = -(m g + F): the particles push it
# down), the ball F, and the ball's centre sits at 2 r + R less both overlaps
# ((m g + F) / kn and F / kn). Also `contacts: false`: no contacts_*.vtp, and with true there are.
set -euo pipefail
source "$(dirname "$0")/script_lib.bash" "$1"
cat > "$tmp/press.yaml" <<YAML
simulation: {duration: "0.3 s", dt: auto}
shapes: [$here/../../shapes/platonic.shp]
bodies:
  - {shape: sphere, position: [0, 0, 0.005], density: 2700}
drivers:
  - wall: {name: floor, point: [0, 0, 0], normal: [0, 0, 1]}
  - ball: {name: press, center: [0, 0, 0.03], radius: 0.02,
           motion: {force: 0.05, direction: [0, 0, -1]}}
forces:
  - gravity_force: {gravity: [0, 0, -9.807]}
  - contact_polyhedron:
      config: {kn: 1.0e4, kt: 1.0e4, mu: 0.5, en: 0.3}
output: {vtk_every: "0.1 s", csv_every: "10 ms", checkpoint_every: "1 s", contacts: false}
YAML
"$polydem" run "$tmp/press.yaml" --out "$tmp/out" > "$tmp/log" 2>&1 || { cat "$tmp/log"; fail "run"; }
python3 - "$tmp/out" <<'PY' || fail "driver CSVs"
import csv, math, sys
out = sys.argv[1]
m = 2700 * 4 / 3 * math.pi * 0.005**3          # kg, the sphere
g, F, kn, r, R = 9.807, 0.05, 1.0e4, 0.005, 0.02
rows = {n: list(csv.DictReader(open(f"{out}/driver_{n}.csv"))) for n in ("floor", "press")}
for n, rs in rows.items():
    times = [float(x["time"]) for x in rs]
    assert len(rs) == 31 and all(abs(t - 0.01 * k) < 1e-4 for k, t in enumerate(times))  # the step nearest each 10 ms, (n, times[:3], len(rs))
floor, press = rows["floor"][-1], rows["press"][-1]
def near(a, b, rel, what):
    assert abs(a - b) <= rel * abs(b), f"{what}: {a} against {b}"
near(-float(floor["fz"]), m * g + F, 1e-4, "floor fz")
near(float(press["fz"]), F, 1e-4, "press fz")
for c in ("fx", "fy"):
    assert abs(float(floor[c])) < 1e-12 and abs(float(press[c])) < 1e-12, c
near(float(press["z"]), 2 * r + R - (m * g + F) / kn - F / kn, 1e-7, "press z")
assert float(press["x"]) == 0 and float(press["y"]) == 0
assert float(floor["z"]) == 0
PY
ls "$tmp"/out/contacts_*.vtp > /dev/null 2>&1 && fail "contacts: false still wrote contacts_*.vtp"
grep -q contacts_ "$tmp/out/scene.pvd" && fail "contacts: false: scene.pvd lists contact files"
sed -i 's/contacts: false/contacts: true/; s/duration: "0.3 s"/duration: "0.1 s"/' "$tmp/press.yaml"
"$polydem" run "$tmp/press.yaml" --out "$tmp/on" > "$tmp/log" 2>&1 || { cat "$tmp/log"; fail "run with contacts"; }
[ "$(ls "$tmp"/on/contacts_*.vtp | wc -l)" -eq 2 ] || fail "contacts: true: expected contacts at 0 and 0.1 s"
echo "driver CSVs match the forces; contacts: false writes no contact files"
