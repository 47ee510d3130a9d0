"""Writes the scale benchmark's scene: n^3 spheres (r = 5 mm) touching in a simple cubic
lattice, the lowest layer on the floor, between four walls 0.5 mm clear of the outer spheres,
under gravity (a settled bed's list pairs, no settling run needed; REST=1 below: at rest).
SHAPE=cube: the same lattice of the library's rounded cubes (side 1 cm, rounding 0.5 mm, axes
along the box's: tools/bench/cubes.yaml's cubes) touching face to face, under contact_polyhedron.
ORDER `lattice` (default) numbers the bodies layer by layer, so neighbours sit near in memory;
`shuffled` lists the same sites in a seeded random order, as a pour leaves them (a body's
neighbours anywhere in memory), in a body table TABLE (a CSV the scene names; its path as
the scene will read it, relative to the scene's folder or absolute). Cubes are always listed
in a table (the lattice generator spaces bodies by their bounding diameter, 16.6 mm for a cube).
REST=1 (the default for cubes; REST=0 turns it off): each layer sits on the one below at the
static overlap of the weight it carries (the law's linear kn), side neighbours 1 um apart (list
pairs, never in contact): at rest from the first step, one contact a body (floor or body below)
at every size. Without it the lattice starts untouched and compresses from the floor up (a wave
of ~8 layers a ms: a larger N is counted with fewer bodies in contact in its first steps), and
the side contacts at zero overlap come and go with the coordinates' rounding.
usage: [SHAPE=sphere|cube] [REST=0|1] python3 scene.py N_SIDE SHAPE_LIBRARY [lattice | shuffled] [TABLE]
       > scene.yaml"""
import os
import random
import sys

n, library = int(sys.argv[1]), sys.argv[2]
order = sys.argv[3] if len(sys.argv) > 3 else "lattice"
table = sys.argv[4] if len(sys.argv) > 4 else None
shape = os.environ.get("SHAPE", "sphere")
if shape not in ("sphere", "cube") or order not in ("lattice", "shuffled"):
    sys.exit(f"scene.py: SHAPE must be sphere or cube (got {shape}), ORDER lattice or shuffled (got {order})")
rest = os.environ.get("REST", "1" if shape == "cube" else "0") == "1"
if table is None and (order == "shuffled" or shape == "cube" or rest):
    sys.exit("scene.py: a shuffled order, SHAPE=cube or REST=1 needs TABLE, the body table's path")
contact = "contact_sphere" if shape == "sphere" else "contact_polyhedron"
kn, g, density, half = 1.0e5, 9.807, 2700.0, 0.005  # N/m, m/s^2, kg/m^3, m: the scene's law, gravity, bodies
pitch = 0.01 + (1e-6 if rest else 0.0)  # m, side neighbours' centres
side = n * pitch + 1e-9  # m, n bodies of 1 cm across, a hair more: the lattice fills the box, centred


def library_volume():  # m^3, the shape's volume in the .shp library
    lines = open(library).read().split("\n")
    at = lines.index(f"name {shape}")
    return next(float(l.split()[1]) for l in lines[at:] if l.startswith("volume "))


def layer_heights():  # m, centre height of each layer: resting on the one below at kn's static overlap
    if not rest:
        return [half + 0.01 * k + 0.5e-9 for k in range(n)]  # the lattice generator's centred sites
    weight = density * library_volume() * g  # N, one body's
    z, heights = half - n * weight / kn, []
    for k in range(n):
        heights.append(z)
        z += 2 * half - (n - k - 1) * weight / kn
    return heights


def bodies_block():
    if order == "lattice" and shape == "sphere" and not rest:
        return f"""  - generate: lattice
    shapes: sphere
    count: {n ** 3}
    region: {{box: {{min: [0, 0, 0], max: [{side}, {side}, {side}]}}}}
    density: 2700"""
    sites = [(i, j, k) for k in range(n) for j in range(n) for i in range(n)]
    if order == "shuffled":
        random.Random(1).shuffle(sites)
    at = lambda i: repr(half + pitch * i + 0.5e-9)  # m, the lattice generator's centred site
    z = [repr(h) for h in layer_heights()]
    with open(table, "w") as out:
        out.write("shape,x,y,z\n")
        out.writelines(f"{shape},{at(i)},{at(j)},{z[k]}\n" for i, j, k in sites)
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
