"""Writes the scale benchmark's scene: n^3 spheres (r = 5 mm) touching in a simple cubic
lattice, the lowest layer on the floor, between four walls 0.5 mm clear of the outer spheres,
at rest under gravity (a settled bed's 3 contacts a sphere, no settling run needed).
usage: python3 scene.py N_SIDE SHAPE_LIBRARY > scene.yaml"""
import sys

n, library = int(sys.argv[1]), sys.argv[2]
side = n * 0.01 + 1e-9  # m, n spheres of diameter 1 cm, a hair more: the lattice fills the box, centred
print(f"""simulation: {{duration: "1 s", dt: "5 us", skin: "0.1 mm", seed: 1}}
shapes: [{library}]
bodies:
  - generate: lattice
    shapes: sphere
    count: {n ** 3}
    region: {{box: {{min: [0, 0, 0], max: [{side}, {side}, {side}]}}}}
    density: 2700
drivers:
  - wall: {{name: floor, point: [0, 0, 0], normal: [0, 0, 1]}}
  - wall: {{name: left, point: [-0.0005, 0, 0], normal: [1, 0, 0]}}
  - wall: {{name: right, point: [{side + 0.0005}, 0, 0], normal: [-1, 0, 0]}}
  - wall: {{name: front, point: [0, -0.0005, 0], normal: [0, 1, 0]}}
  - wall: {{name: back, point: [0, {side + 0.0005}, 0], normal: [0, -1, 0]}}
forces:
  - gravity_force: {{gravity: [0, 0, -9.807]}}
  - contact_sphere:
      config:        {{kn: 1.0e5, kt: 0.8e5, mu: 0.5, en: 0.3}}
      config_driver: {{kn: 1.0e5, kt: 0.8e5, mu: 0.5, en: 0.3}}
output: {{csv_every: "1 s", checkpoint_every: "1 s", contacts: false}}""")
