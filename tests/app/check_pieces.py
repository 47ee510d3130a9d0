"""A distributed run's body pieces against one process's files (issue 20).

usage: check_pieces.py PLAIN_DIR PIECES_DIR RANKS
Each scene.pvd entry of PIECES_DIR names a bodies_NNNNNN.pvtu (well-formed XML, the one
process's arrays declared, one existing piece per rank); the pieces hold every body once; read
as one data set by VTK's parallel reader, its cells sorted by body id carry the very points and
cell data of the one-process bodies_NNNNNN.vtu (bit for bit).
"""
import os
import sys
import xml.etree.ElementTree as ET

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

plain, pieces, ranks = sys.argv[1], sys.argv[2], int(sys.argv[3])
ARRAYS = {"id": "Int64", "group": "Int32", "radius": "Float64", "velocity": "Float64", "angular_velocity": "Float64"}


def read(path, reader):
    reader.SetFileName(path)
    reader.Update()
    assert reader.GetErrorCode() == 0, f"VTK cannot read {path}"
    return reader.GetOutput()


def cells(data):
    """Per cell: its body id, its points' coordinates and its cell data, in body id order
    (a stable sort: a body's cells keep their order)."""
    conn = vtk_to_numpy(data.GetCells().GetConnectivityArray())
    offsets = vtk_to_numpy(data.GetCells().GetOffsetsArray())
    points = vtk_to_numpy(data.GetPoints().GetData())
    ids = vtk_to_numpy(data.GetCellData().GetArray("id"))
    order = np.argsort(ids, kind="stable")
    corners = [points[conn[offsets[c]:offsets[c + 1]]] for c in order]
    values = {name: vtk_to_numpy(data.GetCellData().GetArray(name))[order] for name in ARRAYS}
    return corners, values


def body_ids(path):
    return set(vtk_to_numpy(read(path, vtk.vtkXMLUnstructuredGridReader()).GetCellData().GetArray("id")).tolist())


frames = [d.get("file") for d in ET.parse(os.path.join(pieces, "scene.pvd")).getroot().iter("DataSet")
          if d.get("file").startswith("bodies_")]
assert frames and all(f.endswith(".pvtu") for f in frames), frames
for name in frames:
    root = ET.parse(os.path.join(pieces, name)).getroot()  # well-formed XML
    assert root.get("type") == "PUnstructuredGrid", root.get("type")
    declared = {a.get("Name"): a.get("type") for a in root.iter("PDataArray")}
    assert all(declared.get(k) == v for k, v in ARRAYS.items()), declared
    sources = [p.get("Source") for p in root.iter("Piece")]
    assert len(sources) == ranks, f"{name}: {len(sources)} pieces, expected {ranks}"
    whole = read(os.path.join(plain, name[:-5] + ".vtu"), vtk.vtkXMLUnstructuredGridReader())
    n = len(set(vtk_to_numpy(whole.GetCellData().GetArray("id")).tolist()))
    held = [body_ids(os.path.join(pieces, s)) for s in sources]
    assert sum(len(h) for h in held) == n and set().union(*held) == set(range(n)), \
        f"{name}: the pieces hold {sum(len(h) for h in held)} bodies, {len(set().union(*held))} distinct, of {n}"
    a, b = cells(whole), cells(read(os.path.join(pieces, name), vtk.vtkXMLPUnstructuredGridReader()))
    assert len(a[0]) == len(b[0]) and all(np.array_equal(x, y) for x, y in zip(a[0], b[0])), f"{name}: points differ"
    for k in ARRAYS:
        assert np.array_equal(a[1][k], b[1][k]), f"{name}: cell data '{k}' differs"
print(f"{len(frames)} frames over {ranks} pieces: every body once, the one-process points and cell data")
