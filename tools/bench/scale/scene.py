"""Writes the scale benchmark's scene: n^3 spheres (r = 5 mm) touching in a simple cubic
lattice, the lowest layer on the floor, between four walls 0.5 mm clear of the outer spheres,
at rest under gravity (a settled bed's 3 contacts a sphere, no settling run needed).
SHAPE=cube: the same lattice of the library's rounded cubes (side 1 cm, rounding 0.5 mm, axes
along the box's: tools/bench/cubes.yaml's cubes) touching face to face, under contact_polyhedron.
ORDER `lattice` (default) numbers the bodies layer by layer, so neighbours sit near in memory;
`shuffled` lists the same sites in a seeded random order, as a pour leaves them (a body's
neighbours anywhere in memory), in a body table TABLE (a CSV the scene names; its path as
the scene will read it, relative to the scene's folder or absolute). Cubes are always listed
in a table (the lattice generator spaces bodies by their bounding diameter, 16.6 mm for a cube).
usage: [SHAPE=sphere|cube] python3 scene.py N_SIDE SHAPE_LIBRARY [lattice | shuffled] [TABLE] > scene.yaml"""
import os
import random
import sys

n, library = int(sys.argv[1]), sys.argv[2]
order = sys.argv[3] if len(sys.argv) > 3 else "lattice"
table = sys.argv[4] if len(sys.argv) > 4 else None
shape = os.environ.get("SHAPE", "sphere")
if shape not in ("sphere", "cube") or order not in ("lattice", "shuffled"):
    sys.exit(f"scene.py: SHAPE must be sphere or cube (got {shape}), ORDER lattice or shuffled (got {order})")
if table is None and (order == "shuffled" or shape == "cube"):
    sys.exit("scene.py: a shuffled order or SHAPE=cube needs TABLE, the body table's path")
contact = "contact_sphere" if shape == "sphere" else "contact_polyhedron"
side = n * 0.01 + 1e-9  # m, n spheres of diameter 1 cm, a hair more: the lattice fills the box, centred


def bodies_block():
    if order == "lattice" and shape == "sphere":
        return f"""  - generate: lattice
    shapes: sphere
    count: {n ** 3}
    region: {{box: {{min: [0, 0, 0], max: [{side}, {side}, {side}]}}}}
    density: 2700"""
    sites = [(i, j, k) for k in range(n) for j in range(n) for i in range(n)]
    if order == "shuffled":
        random.Random(1).shuffle(sites)
    at = lambda i: repr(0.005 + 0.01 * i + 0.5e-9)  # m, the lattice generator's centred site
    with open(table, "w") as out:
        out.write("shape,x,y,z\n")
        out.writelines(f"{shape},{at(i)},{at(j)},{at(k)}\n" for i, j, k in sites)
    return f"  - {{file: {table}, density: 2700}}"


print(f"""simulation: {{duration: "1 s", dt: "5 us", skin: "0.1 mm", seed: 1}}
shapes: [{library}]
bodies:
{bodies_block()}
drivers:
  - wall: {{name: floor, point: [0, 0, 0], normal: [0, 0, 1]}}
  - wall: {{name: left, point: [-0.0005, 0, 0], normal: [1, 0, 0]}}
  - wall: {{name: right, point: [{side + 0.0005}, 0, 0], normal: [-1, 0, 0]}}
  - wall: {{name: front, point: [0, -0.0005, 0], normal: [0, 1, 0]}}
  - wall: {{name: back, point: [0, {side + 0.0005}, 0], normal: [0, -1, 0]}}
forces:
  - gravity_force: {{gravity: [0, 0, -9.807]}}
  - {contact}:
      config:        {{kn: 1.0e5, kt: 0.8e5, mu: 0.5, en: 0.3}}
      config_driver: {{kn: 1.0e5, kt: 0.8e5, mu: 0.5, en: 0.3}}
output: {{csv_every: "1 s", checkpoint_every: "1 s", contacts: false}}""")
