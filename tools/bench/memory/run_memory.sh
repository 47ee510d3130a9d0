#!/usr/bin/env bash
# Peak memory per body: a simple cubic lattice of touching spheres (r = 5 mm, the bench bed's
# material; 3 neighbour pairs per sphere within the skin, as many as a settled bed has) of
# n^3 bodies falling at 0.5 m/s, 40 steps under /usr/bin/time -v: three list builds, the later
# ones with the old and the new lists both held (the peak of a long run). Prints
# "bodies peak_kB kB_per_body"; the per-body figure is peak / bodies, and the marginal cost
# between two sizes is the slope.
# SHAPE=cube: a lattice of rounded cubes (side 1 cm) under contact_polyhedron, at the lattice
# generator's spacing, the bounding diameter (16.6 mm): the cubes do not touch, so this is the
# memory of the bodies and their poses, not of contacts.
# usage: [SHAPE=cube] tools/bench/memory/run_memory.sh [POLYDEM] [N ...]   (N per side; default 15 30 45)
# Rows measured so far: tools/bench/memory/results.csv (README, Benchmarks).
set -euo pipefail
cd "$(dirname "$0")/../../.."
bin=$(realpath "${1:-build/polydem}")
shift || true
sides=("${@:-15 30 45}")
shape=${SHAPE:-sphere}
case "$shape" in
  sphere) contact=contact_sphere; pitch=0.01 ;;      # m, touching
  cube) contact=contact_polyhedron; pitch=0.0166 ;;  # m, > 2 x the bounding radius 8.29 mm
  *) echo "run_memory.sh: SHAPE must be sphere or cube, not '$shape'" >&2; exit 1 ;;
esac
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for n in ${sides[@]}; do
  side=$(python3 -c "print($n * $pitch + 0.001)")
  cat > "$work/scene.yaml" <<YAML
simulation: {duration: "1 s", dt: "5 us", skin: "0.1 mm", seed: 1}
shapes: [$PWD/shapes/platonic.shp]
bodies:
  - generate: lattice
    shapes: $shape
    count: $((n * n * n))
    region: {box: {min: [0, 0, 0.0005], max: [$side, $side, $(python3 -c "print($side + 0.0005)")]}}
    velocity: [0, 0, -0.5]
    density: 2700
drivers:
  - wall: {name: floor, point: [0, 0, 0], normal: [0, 0, 1]}
forces:
  - gravity_force: {gravity: [0, 0, -9.807]}
  - $contact:
      config:        {kn: 1.0e5, kt: 0.8e5, mu: 0.5, en: 0.3}
      config_driver: {kn: 1.0e5, kt: 0.8e5, mu: 0.5, en: 0.3}
output: {csv_every: "1 s", checkpoint_every: "1 s", contacts: false}
YAML
  rm -rf "$work/out"
  /usr/bin/time -v "$bin" run "$work/scene.yaml" --out "$work/out" --threads 1 --until 2e-4 \
      > /dev/null 2> "$work/log" || { cat "$work/log"; exit 1; }
  peak=$(grep 'Maximum resident' "$work/log" | awk '{print $NF}')
  bodies=$((n * n * n))
  echo "$bodies $peak $(python3 -c "print(round($peak / $bodies, 3))")"
done
