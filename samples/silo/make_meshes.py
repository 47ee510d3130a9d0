#!/usr/bin/python3
"""Flat silo bottoms with a central circular orifice: one ASCII STL annulus per orifice size.

meshes/plate_D<mm>.stl: the ring between radius D/2 (the orifice) and OUTER (beyond the silo
wall, so no gap at the corner) in the plane z = 0, normals +z; the circles are polygons of
SEGMENTS sides (orifice area within 0.2% of the circle's). Usage: make_meshes.py [D_mm ...]
"""
import math
import os
import sys

OUTER = 0.07      # m, plate radius (the silo radius is 0.06 m)
SEGMENTS = 64


def annulus(inner, outer, segments):
    """Triangles (3 points each) of the ring inner < r < outer at z = 0, counter-clockwise from +z."""
    def ring(r, k):
        a = 2.0 * math.pi * k / segments
        return (r * math.cos(a), r * math.sin(a), 0.0)
    triangles = []
    for k in range(segments):
        a, b = ring(inner, k), ring(inner, k + 1)
        c, d = ring(outer, k + 1), ring(outer, k)
        triangles += [(a, d, c), (a, c, b)]
    return triangles


def write_stl(path, name, triangles):
    with open(path, "w") as f:
        f.write(f"solid {name}\n")
        for t in triangles:
            f.write("  facet normal 0 0 1\n    outer loop\n")
            for p in t:
                f.write(f"      vertex {p[0]:.9g} {p[1]:.9g} {p[2]:.9g}\n")
            f.write("    endloop\n  endfacet\n")
        f.write(f"endsolid {name}\n")


def main():
    sizes = [int(s) for s in sys.argv[1:]] or [45, 50, 60]
    here = os.path.dirname(os.path.abspath(__file__))
    os.makedirs(os.path.join(here, "meshes"), exist_ok=True)
    for d in sizes:
        path = os.path.join(here, "meshes", f"plate_D{d}.stl")
        write_stl(path, f"plate_D{d}", annulus(0.0005 * d, OUTER, SEGMENTS))
        print(path)


if __name__ == "__main__":
    main()
