"""What a user reads of a run stored in space order equals the run in input order (issue 19).

usage: body_order.py SPACE_DIR INPUT_DIR FRAME
Both folders hold the same scene's run (--body-order space, --body-order input) to the same
time. Their bodies_FRAME.vtu list the same bodies in the same order under the same ids, with
points and velocities equal to 1e-9 of the scene's size and speed (the sums run in another order:
round-off apart); each final checkpoint (format 08) stores the user id of every stored body: the
space run's are not the identity (its order differs from the input's), the input run's are.
"""
import array
import glob
import re
import struct
import sys


def vtu_arrays(path):
    """The appended raw arrays of a polydem .vtu by name (UInt64 byte-count headers)."""
    data = open(path, "rb").read()
    mark = b'<AppendedData encoding="raw">\n_'
    start = data.index(mark) + len(mark)
    kinds = {"Float64": "d", "Int64": "q", "Int32": "i", "UInt8": "B"}
    arrays = {}
    for m in re.finditer(rb'<DataArray type="(\w+)" Name="(\w+)"[^>]*offset="(\d+)"', data[:start]):
        kind, name, offset = kinds.get(m.group(1).decode(), "B"), m.group(2).decode(), int(m.group(3))
        (size,) = struct.unpack_from("<Q", data, start + offset)
        arrays[name] = array.array(kind, data[start + offset + 8:start + offset + 8 + size])
    return arrays


def stored_ids(folder):
    """The user id of each stored body in the folder's last checkpoint."""
    path = sorted(glob.glob(f"{folder}/checkpoint_*.bin"))[-1]
    data = open(path, "rb").read()
    assert data[:8] == b"PDCKPT08", f"{path}: {data[:8]!r}, expected format 08"
    (n,) = struct.unpack_from("<Q", data, 40)
    return list(struct.unpack_from(f"<{n}I", data, 48))


space_dir, input_dir, frame = sys.argv[1], sys.argv[2], sys.argv[3]
a = vtu_arrays(f"{space_dir}/bodies_{frame}.vtu")
b = vtu_arrays(f"{input_dir}/bodies_{frame}.vtu")
assert a["id"] == b["id"], "the bodies' ids or their order differ"
assert list(a["id"]) == sorted(a["id"]), "bodies not listed by id"
for name in ("group", "radius", "types", "connectivity"):
    assert a[name] == b[name], f"{name} differs"
for name in ("Points", "velocity"):
    scale = max(abs(x) for x in b[name])
    apart = max(abs(x - y) for x, y in zip(a[name], b[name])) / scale
    print(f"{name}: {apart:.3g} of {scale:.3g} apart")
    assert apart < 1e-9, f"{name}: {apart:.3g} relative"
space, plain = stored_ids(space_dir), stored_ids(input_dir)
identity = list(range(len(space)))
assert sorted(space) == identity, "the space run's ids are not a permutation"
assert space != identity, "the scene's space order is its input order: no test"
assert plain == identity, "the input run is not stored in the scene's order"
print(f"same bodies under the same ids; {sum(s != k for k, s in enumerate(space))} of {len(space)} stored elsewhere")
