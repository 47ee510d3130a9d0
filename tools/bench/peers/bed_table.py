#!/usr/bin/env python3
"""The settled bed (a format-06 to 08 checkpoint of tools/bench/peers/spheres.yaml) as two body
tables: bodies_id.csv in user id order (08 stores its bodies in the run's order and the user id
of each) and bodies_cell.csv
sorted by cell (1 cm cubes, about a sphere's diameter; z, then y, then x, ties by id), the
same state in space order. Positions, velocities and spins only: contacts restart new.
usage: bed_table.py SETTLED.bin OUT_DIR"""
import math
import struct
import sys

CELL = 0.01  # m, a sphere's diameter in the bed


def read_state(path):
    data = open(path, "rb").read()
    if data[:8] not in (b"PDCKPT06", b"PDCKPT07", b"PDCKPT08"):  # the same bodies' arrays
        sys.exit(f"{path}: not a format-06 to 08 polydem checkpoint")
    bodies = struct.unpack_from("<4Q", data, 8)[1]
    at = 40
    ids = list(range(bodies))
    if data[:8] == b"PDCKPT08":  # the user id of each stored body
        ids = struct.unpack_from(f"<{bodies}I", data, at + 8)
        at += 8 + 4 * bodies
    at += 8 + 8 + 9 * 8  # step, dt, energy ledger (9 doubles)

    def array(width):
        nonlocal at
        (n,) = struct.unpack_from("<Q", data, at)
        assert n == bodies, (n, bodies)
        values = [None] * n
        for k in range(n):
            values[ids[k]] = struct.unpack_from(f"<{width}d", data, at + 8 + 8 * width * k)
        at += 8 + 8 * width * n
        return values

    position, _, velocity, spin = array(3), array(4), array(3), array(3)
    return position, velocity, spin


def write(path, order, position, velocity, spin):
    with open(path, "w") as f:
        f.write("shape,x,y,z,vx,vy,vz,wx,wy,wz\n")
        for k in order:
            f.write("sphere," + ",".join(repr(x) for x in (*position[k], *velocity[k], *spin[k])) + "\n")


def main():
    position, velocity, spin = read_state(sys.argv[1])
    ids = range(len(position))
    cell = lambda k: tuple(math.floor(position[k][a] / CELL) for a in (2, 1, 0))
    write(f"{sys.argv[2]}/bodies_id.csv", ids, position, velocity, spin)
    write(f"{sys.argv[2]}/bodies_cell.csv", sorted(ids, key=lambda k: (cell(k), k)), position, velocity, spin)


main()
