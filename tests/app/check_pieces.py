"""A distributed run's VTK pieces against one process's files (issue 20).

usage: check_pieces.py PLAIN_DIR PIECES_DIR RANKS
Each bodies and contacts entry of PIECES_DIR's scene.pvd names a bodies_NNNNNN.pvtu or a
contacts_NNNNNN.pvtp (well-formed XML, the one process's arrays declared, one existing piece
per rank); the body pieces hold every body once; read as one data set by VTK's parallel
reader, its cells sorted by body id (contacts: by pair) carry the very points and cell data of
the one-process .vtu (.vtp), bit for bit.
"""
import os
import sys
import xml.etree.ElementTree as ET

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

plain, pieces, ranks = sys.argv[1], sys.argv[2], int(sys.argv[3])
BODY_ARRAYS = {"id": "Int64", "group": "Int32", "radius": "Float64", "velocity": "Float64",
               "angular_velocity": "Float64"}
CONTACT_ARRAYS = {"force": "Float64", "point": "Float64", "fn": "Float64", "ft": "Float64", "overlap": "Float64",
                  "i": "Int64", "j": "Int64", "type": "Int32"}


def read(path, reader):
    reader.SetFileName(path)
    reader.Update()
    assert reader.GetErrorCode() == 0, f"VTK cannot read {path}"
    return reader.GetOutput()


def cells(data, arrays):
    """Per cell, its points' coordinates and its cell data, in (id) or (i, j) order (a stable
    sort: a body's cells keep their order; a pair is one line)."""
    if data.GetNumberOfCells() == 0:
        return [], {}
    if isinstance(data, vtk.vtkPolyData):
        cell_array = data.GetLines()
        key = vtk_to_numpy(data.GetCellData().GetArray("i")) * 2**32 + vtk_to_numpy(data.GetCellData().GetArray("j"))
    else:
        cell_array = data.GetCells()
        key = vtk_to_numpy(data.GetCellData().GetArray("id"))
    conn = vtk_to_numpy(cell_array.GetConnectivityArray())
    offsets = vtk_to_numpy(cell_array.GetOffsetsArray())
    points = vtk_to_numpy(data.GetPoints().GetData())
    order = np.argsort(key, kind="stable")
    corners = [points[conn[offsets[c]:offsets[c + 1]]] for c in order]
    values = {name: vtk_to_numpy(data.GetCellData().GetArray(name))[order] for name in arrays}
    return corners, values


def same(name, a, b):
    assert len(a[0]) == len(b[0]) and all(np.array_equal(x, y) for x, y in zip(a[0], b[0])), f"{name}: points differ"
    for k in a[1]:
        assert np.array_equal(a[1][k], b[1][k]), f"{name}: cell data '{k}' differs"


def body_ids(path):
    return set(vtk_to_numpy(read(path, vtk.vtkXMLUnstructuredGridReader()).GetCellData().GetArray("id")).tolist())


def declared(path, kind, arrays, ranks):
    """The sources of a parallel file, checked: well-formed, its kind, arrays and piece count."""
    root = ET.parse(path).getroot()  # well-formed XML
    assert root.get("type") == kind, root.get("type")
    found = {a.get("Name"): a.get("type") for a in root.iter("PDataArray")}
    assert all(found.get(k) == v for k, v in arrays.items()), found
    sources = [p.get("Source") for p in root.iter("Piece")]
    assert len(sources) == ranks, f"{path}: {len(sources)} pieces, expected {ranks}"
    assert all(os.path.exists(os.path.join(os.path.dirname(path), f)) for f in sources), sources
    return sources


files = [d.get("file") for d in ET.parse(os.path.join(pieces, "scene.pvd")).getroot().iter("DataSet")]
bodies = [f for f in files if f.startswith("bodies_")]
contacts = [f for f in files if f.startswith("contacts_")]
assert bodies and all(f.endswith(".pvtu") for f in bodies), bodies
assert all(f.endswith(".pvtp") for f in contacts), contacts
touching = 0
for name in bodies:
    sources = declared(os.path.join(pieces, name), "PUnstructuredGrid", BODY_ARRAYS, ranks)
    whole = read(os.path.join(plain, name[:-5] + ".vtu"), vtk.vtkXMLUnstructuredGridReader())
    n = len(set(vtk_to_numpy(whole.GetCellData().GetArray("id")).tolist()))
    held = [body_ids(os.path.join(pieces, s)) for s in sources]
    assert sum(len(h) for h in held) == n and set().union(*held) == set(range(n)), \
        f"{name}: the pieces hold {sum(len(h) for h in held)} bodies, {len(set().union(*held))} distinct, of {n}"
    same(name, cells(whole, BODY_ARRAYS), cells(read(os.path.join(pieces, name), vtk.vtkXMLPUnstructuredGridReader()),
                                                BODY_ARRAYS))
for name in contacts:
    declared(os.path.join(pieces, name), "PPolyData", CONTACT_ARRAYS, ranks)
    whole = read(os.path.join(plain, name[:-5] + ".vtp"), vtk.vtkXMLPolyDataReader())
    touching += whole.GetNumberOfCells()
    same(name, cells(whole, CONTACT_ARRAYS),
         cells(read(os.path.join(pieces, name), vtk.vtkXMLPPolyDataReader()), CONTACT_ARRAYS))
print(f"{len(bodies)} body and {len(contacts)} contact frames over {ranks} pieces ({touching} touching pairs): "
      f"every body once, the one-process points and cell data")
