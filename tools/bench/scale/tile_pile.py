"""Writes a large settled bed of cubes: TILES x TILES copies of the settled 3,375-cube pile of
tools/bench/cubes.yaml (its checkpoint, a 16 cm x 16 cm box) side by side in x and y, one box
width (0.16 m) apart: one floor, four outer walls, and the copies' inner walls, whose planes two
copies share, as one STL driver of two-sided rectangles (walls are infinite planes; a mesh's
face is two-sided and ends). 1 tile is the pile itself, 17 tiles 975,375 cubes.
Writes the body table TABLE (CSV, one cube a row, copy by copy in the pile's order; its path as
the scene will read it, relative to the scene's folder or absolute), the seams' mesh beside it
(TABLE less .csv, plus _seams.stl) and prints the scene: the pile's contact law, gravity, skin
and time step (the checkpoint's, to the bit). A run of it from the table alone starts the
contacts' springs at zero and the bed moves (~4 mm/s at 1 x 1 in its first 10 ms, 8 list
builds in 2,304 steps where the pile's checkpoint takes 2).
With OUT_CHECKPOINT it also writes the tiled state as a checkpoint at step 0: each copy's bodies
(positions, orientations, velocities, momenta, forces) and contacts (springs, records, pending
energies), the energy ledger summed over the copies; the contacts with the inner walls are left
out (the seams' mesh makes them again at the first list build, same planes and law, springs at
zero). `polydem run scene.yaml --resume OUT_CHECKPOINT --force` (the fingerprint is the pile's:
--force) starts at rest up to the seams' tangential springs. 1 tile: the pile's checkpoint but
its step (0) and output frames. Its body order is copy by copy, each copy in the pile's space
order (a fresh run of the table sorts the whole bed by cell instead: simulation: body_order).
usage: python3 tile_pile.py TILES CHECKPOINT SHAPE_LIBRARY TABLE [OUT_CHECKPOINT] > scene.yaml
       (CHECKPOINT: build/bench/cubes/settled.bin, one process's format-08 file)"""
import ctypes
import os
import struct
import subprocess
import sys
import tempfile

kHalfWidth = 0.08  # m, tools/bench/cubes.yaml's walls at x, y = +-0.08
kPitch = 2 * kHalfWidth  # m, one copy to the next: the box's width
kWalls = {"left": 1, "right": 2, "front": 3, "back": 4}  # driver index in cubes.yaml (0: floor)
kHeader = struct.Struct("<8s4Q")  # magic; fingerprint, bodies, drivers, payload bytes
kLedger = struct.Struct("<3d3d3d")  # dissipated, driver and external work; mass moment at t = 0 (kg m); 3 shares
kContactBytes = 152  # sim/checkpoint_io.hpp slot_fields with the pair: i j type a b state ft mr point force fn gap fd gap weight
kPointAt = 2 * 4 + 1 + 2 + 4 + 1 + 2 * 24  # bytes into a contact record: its point (m, world)
kEnergyBytes = 32  # a pair's pending EnergyParts
kDriverBytes = 1 + 9 * 24 + 32  # driver_fields: active, 9 Vec3 (point first), orientation


class Reader:
    def __init__(self, data):
        self.data, self.at = data, 0

    def take(self, size):
        self.at += size
        return self.data[self.at - size:self.at]

    def u64(self):
        return struct.unpack("<Q", self.take(8))[0]

    def array(self, width):  # a counted array of `width`-byte entries, raw
        return self.take(width * self.u64())


def read_contacts(r):  # -> (records, pair starts, energies): one process's active slots by pair
    raw = r.array(kContactBytes)
    starts = [k for k in range(0, len(raw), kContactBytes) if k == 0 or raw[k:k + 8] != raw[k - kContactBytes:k - kContactBytes + 8]]
    return raw, starts, r.take(kEnergyBytes * len(starts))


def read_pile(path):
    data = open(path, "rb").read()
    magic, fingerprint, bodies, drivers, _ = kHeader.unpack_from(data)
    if magic != b"PDCKPT08":
        sys.exit(f"tile_pile.py: {path} is not one process's format-08 checkpoint")
    r = Reader(data)
    r.at = kHeader.size
    p = {"fingerprint": fingerprint, "drivers": drivers}
    p["ids"] = struct.unpack(f"<{bodies}I", r.array(4))
    p["step"], p["dt"] = struct.unpack("<qd", r.take(16))
    p["ledger"] = kLedger.unpack(r.take(kLedger.size))
    p["state"] = [r.array(32 if k == 1 else 24) for k in range(7)]  # position, orientation (x y z w), v, w, L, F, T
    r.u64()
    p["driver_fields"] = [r.take(kDriverBytes) for _ in range(drivers)]
    p["body_contacts"], p["driver_contacts"] = read_contacts(r), read_contacts(r)
    p["flushed"] = struct.unpack(f"<{r.u64()}q", r.take(8 * 280))  # 4 exact sums of 70 words
    return p


def user_rows(p):  # (position, quaternion w x y z, velocity, angular velocity) by user id
    f = [struct.unpack(f"<{len(a) // 8}d", a) for a in p["state"][:4]]
    rows = [None] * len(p["ids"])
    for k, user in enumerate(p["ids"]):
        x, y, z, w = f[1][4 * k:4 * k + 4]
        rows[user] = (f[0][3 * k:3 * k + 3], (w, x, y, z), f[2][3 * k:3 * k + 3], f[3][3 * k:3 * k + 3])
    return rows  # the cube's input_rotation is the identity: the stored quaternion is the table's


def write_table(path, rows, tiles):
    with open(path, "w") as out:
        out.write("shape,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz\n")
        for ty in range(tiles):
            for tx in range(tiles):
                for (x, y, z), q, v, w in rows:
                    cells = (x + tx * kPitch, y + ty * kPitch, z) + q + v + w
                    out.write("cube," + ",".join(repr(c) for c in cells) + "\n")


def fnv1a():  # the checkpoint's checksum (sim/scene_fingerprint.cpp), compiled: Python takes ~0.3 us a byte
    folder = tempfile.mkdtemp()
    source, lib = os.path.join(folder, "fnv.c"), os.path.join(folder, "fnv.so")
    open(source, "w").write("#include <stdint.h>\n#include <stddef.h>\nuint64_t fnv(const unsigned char* d, size_t n, "
                            "uint64_t h) { for (size_t k = 0; k < n; ++k) h = (h ^ d[k]) * 1099511628211ull; return h; }\n")
    subprocess.run(["cc", "-O2", "-shared", "-fPIC", source, "-o", lib], check=True)
    f = ctypes.CDLL(lib).fnv
    f.restype, f.argtypes = ctypes.c_uint64, [ctypes.c_char_p, ctypes.c_size_t, ctypes.c_uint64]
    return f


class Sealed:  # a file with its running checksum, sealed by it at the end
    def __init__(self, path):
        self.out, self.hash, self.fnv = open(path, "wb"), 14695981039346656037, fnv1a()

    def write(self, data):
        self.out.write(data)
        self.hash = self.fnv(data, len(data), self.hash)

    def close(self):
        self.out.write(struct.pack("<Q", self.hash))
        self.out.close()


def shifted(raw, offsets, stride, at, shift):  # Vec3s at `at` of each `stride`-byte entry, plus shift
    out = bytearray(raw)
    for k in offsets:
        x, y, z = struct.unpack_from("<3d", raw, k + at)
        struct.pack_into("<3d", out, k + at, x + shift[0], y + shift[1], z)
    return bytes(out)


def tile_contacts(contacts, n, tile, shift, kept):  # one copy's records and energies
    raw, starts, energies = contacts
    ends = starts[1:] + [len(raw)]
    records, parts = bytearray(), bytearray()
    for p, (a, b) in enumerate(zip(starts, ends)):
        i, j = struct.unpack_from("<II", raw, a)
        if not kept(j):
            continue
        block = bytearray(shifted(raw[a:b], range(0, b - a, kContactBytes), kContactBytes, kPointAt, shift))
        for k in range(0, b - a, kContactBytes):
            struct.pack_into("<II", block, k, i + tile * n, j + (tile * n if kept is all_bodies else 0))
        records += block
        parts += energies[kEnergyBytes * p:kEnergyBytes * (p + 1)]
    return bytes(records), bytes(parts)


def all_bodies(j):
    return True


def write_checkpoint(path, p, tiles):
    n, copies = len(p["ids"]), tiles * tiles
    shifts = [(tx * kPitch, ty * kPitch) for ty in range(tiles) for tx in range(tiles)]
    mass = n * 2700.0 * 9.9372934918732955e-07  # kg, the pile's: cubes.yaml's density, platonic.shp's volume
    led = list(p["ledger"])
    moment = [copies * led[3] + mass * sum(s[0] for s in shifts), copies * led[4] + mass * sum(s[1] for s in shifts),
              copies * led[5]]
    ledger = kLedger.pack(*[copies * v for v in led[:3]], *moment, *[copies * v for v in led[6:]])
    parts = [struct.pack(f"<Q{n * copies}I", n * copies, *[t * n + u for t in range(copies) for u in p["ids"]]),
             struct.pack("<qd", 0, p["dt"]), ledger]
    for k, a in enumerate(p["state"]):
        parts.append(struct.pack("<Q", len(a) // (32 if k == 1 else 24) * copies))
        parts += [shifted(a, range(0, len(a), 24), 24, 0, s) for s in shifts] if k == 0 else [a] * copies
    parts.append(struct.pack("<Q", p["drivers"] + (tiles > 1)))
    far = (tiles - 1) * kPitch  # m, the outer walls' shift
    for d, fields in enumerate(p["driver_fields"]):
        parts.append(shifted(fields, [0], 0, 1, (far, 0) if d == kWalls["right"] else (0, far) if d == kWalls["back"]
                             else (0, 0)))
    if tiles > 1:  # the seams' mesh, at rest where the scene puts it: centre 0, normal x, axis y (mesh_driver.cpp)
        parts.append(struct.pack("<B3d3d3d3d3d3d3d3d3d4d", 1, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1, 0, *[0] * 15, 0, 0, 0, 1))
    body = [tile_contacts(p["body_contacts"], n, t, s, all_bodies) for t, s in enumerate(shifts)]
    driver = [tile_contacts(p["driver_contacts"], n, t, s, walls_kept(t, tiles)) for t, s in enumerate(shifts)]
    for lists in (body, driver):
        parts.append(struct.pack("<Q", sum(len(r) for r, _ in lists) // kContactBytes))
        parts += [r for r, _ in lists] + [e for _, e in lists]
    parts.append(struct.pack("<Q280q", 280, *[copies * w for w in p["flushed"]]))  # exact sums: digits add
    parts.append(struct.pack("<qQ", 0, 0))  # output progress: no frame yet
    out = Sealed(path)
    drivers = p["drivers"] + (tiles > 1)
    out.write(kHeader.pack(b"PDCKPT08", p["fingerprint"], n * copies, drivers, sum(len(x) for x in parts)))
    for x in parts:
        out.write(x)
    out.close()


def write_seams(path, tiles):
    """The inner walls' planes x, y = 0.08 + 0.16 k as rectangles from below the floor to above the
    pile and past the outer walls (their rims out of the cubes' reach), cut at the copies' centres
    (not where two planes cross: an edge of four faces) into pairs of triangles."""
    low, high = -kHalfWidth - 0.01, kHalfWidth + (tiles - 1) * kPitch + 0.01  # m
    cuts = [low] + [kPitch * k for k in range(tiles)] + [high]  # m, along the seam
    bottom, top = -0.01, 0.4  # m: the floor is z = 0, the pile's top z = 0.28
    with open(path, "w") as out:
        out.write("solid seams\n")
        for k in range(tiles - 1):
            at = kHalfWidth + k * kPitch
            for a, b in zip(cuts, cuts[1:]):
                for place in (lambda u, z: (at, u, z), lambda u, z: (u, at, z)):  # x = at, then y = at
                    corners = [place(a, bottom), place(b, bottom), place(b, top), place(a, top)]
                    for tri in ((0, 1, 2), (0, 2, 3)):
                        out.write(" facet normal 0 0 0\n  outer loop\n")
                        out.writelines(f"   vertex {c[0]!r} {c[1]!r} {c[2]!r}\n" for c in (corners[t] for t in tri))
                        out.write("  endloop\n endfacet\n")
        out.write("endsolid seams\n")


def walls_kept(tile, tiles):  # the walls a copy keeps: those on the bed's outside
    tx, ty = tile % tiles, tile // tiles
    dropped = {kWalls["left"]} if tx > 0 else set()
    dropped |= {kWalls["right"]} if tx < tiles - 1 else set()
    dropped |= {kWalls["front"]} if ty > 0 else set()
    dropped |= {kWalls["back"]} if ty < tiles - 1 else set()
    return lambda j: j not in dropped


def main():
    if len(sys.argv) not in (5, 6):
        sys.exit(__doc__)
    tiles, checkpoint, library, table = int(sys.argv[1]), sys.argv[2], sys.argv[3], sys.argv[4]
    pile = read_pile(checkpoint)
    write_table(table, user_rows(pile), tiles)
    seams = table[:-4] + "_seams.stl" if table.endswith(".csv") else table + "_seams.stl"
    if tiles > 1:
        write_seams(seams, tiles)
    if len(sys.argv) == 6:
        write_checkpoint(sys.argv[5], pile, tiles)
    far = kHalfWidth + (tiles - 1) * kPitch  # m, the last copy's outer walls
    seams_driver = f"\n  - stl: {{name: seams, file: {seams}}}" if tiles > 1 else ""
    print(f"""# {tiles} x {tiles} copies of the settled pile {checkpoint}: {tiles * tiles * len(pile['ids'])} cubes
simulation: {{duration: "1 s", dt: "{pile['dt']!r} s", skin: "0.1 mm", seed: 1}}
shapes: [{library}]
bodies:
  - {{file: {table}, density: 2700}}
drivers:
  - wall: {{name: floor, point: [0, 0, 0], normal: [0, 0, 1]}}
  - wall: {{name: left, point: [{-kHalfWidth}, 0, 0], normal: [1, 0, 0]}}
  - wall: {{name: right, point: [{far!r}, 0, 0], normal: [-1, 0, 0]}}
  - wall: {{name: front, point: [0, {-kHalfWidth}, 0], normal: [0, 1, 0]}}
  - wall: {{name: back, point: [0, {far!r}, 0], normal: [0, -1, 0]}}{seams_driver}
forces:
  - gravity_force: {{gravity: [0, 0, -9.807]}}
  - contact_polyhedron:
      config:        {{kn: 1.0e5, kt: 0.8e5, mu: 0.5, en: 0.3}}
      config_driver: {{kn: 1.0e5, kt: 0.8e5, mu: 0.5, en: 0.3}}
output: {{csv_every: "1 s", checkpoint_every: "1 s", contacts: false}}""")


if __name__ == "__main__":
    main()
