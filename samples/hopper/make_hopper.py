#!/usr/bin/python3
"""A conical hopper with a vertical bin above it, as one ASCII STL mesh (meshes/hopper.stl).

The cone runs from the outlet (radius OUTLET / 2 at z = 0) up to radius TOP at half-angle
ANGLE from the vertical, then a vertical wall of height BIN; both are open (no lid, no
bottom). Circles are polygons of SEGMENTS sides; the walls are cut in rings about STEP high
so that no triangle spans much more than a particle (the mesh's spatial index stays sharp).
Normals point inwards. Usage: make_hopper.py [OUTLET_mm] (default 50).
"""
import math
import os
import sys

TOP = 0.07            # m, radius of the bin
ANGLE = 30.0          # deg, cone half-angle from the vertical
BIN = 0.15            # m, height of the vertical wall above the cone
SEGMENTS = 48
STEP = 0.015          # m, ring height


def profile(outlet):
    """(radius, z) of the rings from the outlet up."""
    r0 = 0.5 * outlet
    cone = (TOP - r0) / math.tan(math.radians(ANGLE))
    rings = []
    n = max(1, round(cone / STEP))
    rings += [(r0 + (TOP - r0) * i / n, cone * i / n) for i in range(n + 1)]
    m = max(1, round(BIN / STEP))
    rings += [(TOP, cone + BIN * i / m) for i in range(1, m + 1)]
    return rings, cone


def triangles(rings):
    def point(r, z, k):
        a = 2.0 * math.pi * k / SEGMENTS
        return (r * math.cos(a), r * math.sin(a), z)
    out = []
    for (r0, z0), (r1, z1) in zip(rings, rings[1:]):
        for k in range(SEGMENTS):
            a, b = point(r0, z0, k), point(r0, z0, k + 1)
            c, d = point(r1, z1, k + 1), point(r1, z1, k)
            out += [(a, c, b), (a, d, c)]  # clockwise seen from outside: normals inwards
    return out


def write_stl(path, name, tris):
    with open(path, "w") as f:
        f.write(f"solid {name}\n")
        for t in tris:
            f.write("  facet normal 0 0 0\n    outer loop\n")
            for p in t:
                f.write(f"      vertex {p[0]:.9g} {p[1]:.9g} {p[2]:.9g}\n")
            f.write("    endloop\n  endfacet\n")
        f.write(f"endsolid {name}\n")


def main():
    outlet = (float(sys.argv[1]) if len(sys.argv) > 1 else 50.0) / 1000.0
    rings, cone = profile(outlet)
    here = os.path.dirname(os.path.abspath(__file__))
    os.makedirs(os.path.join(here, "meshes"), exist_ok=True)
    path = os.path.join(here, "meshes", "hopper.stl")
    tris = triangles(rings)
    write_stl(path, "hopper", tris)
    print(f"{path}: {len(tris)} triangles, outlet {outlet * 1000:.0f} mm, cone height {cone * 1000:.1f} mm, "
          f"top of the bin at z = {rings[-1][1] * 1000:.1f} mm")


if __name__ == "__main__":
    main()
