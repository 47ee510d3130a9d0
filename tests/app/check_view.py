"""Checks the box-fill sample's first view: every .pvd series opens in VTK's readers with its
arrays and the same times as scene.pvd, and the five walls are the faces of the box.
usage: check_view.py OUTPUT_DIR"""
import os
import sys
import xml.etree.ElementTree as ET

import numpy as np

try:
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLUnstructuredGridReader
except ImportError:
    sys.exit("python3-vtk9 is missing: apt-get install python3-vtk9")

out = sys.argv[1]
HALF = 0.1  # m, the box's walls are at x, y = +-0.1 and z = 0 (samples/box-fill/scene.yaml)
TOL = 1e-12  # m
ARRAYS = {"bodies": {"id", "group", "radius", "velocity", "angular_velocity"},
          "drivers": {"driver"},
          "contacts": {"force", "fn", "ft", "overlap", "point", "i", "j", "type"}}
PLANES = {"floor": ([0, 0, 0], [0, 0, 1]), "left": ([-HALF, 0, 0], [1, 0, 0]), "right": ([HALF, 0, 0], [-1, 0, 0]),
          "front": ([0, -HALF, 0], [0, 1, 0]), "back": ([0, HALF, 0], [0, -1, 0])}


def series(name):
    sets = ET.parse(os.path.join(out, name)).getroot().find("Collection").findall("DataSet")
    return [(float(d.get("timestep")), d.get("file"), int(d.get("part"))) for d in sets]


def read(path):
    reader = vtkXMLUnstructuredGridReader() if path.endswith(".vtu") else vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    assert reader.GetErrorCode() == 0, f"VTK could not read {path}"
    return reader.GetOutput()


def polygons(data):
    points = vtk_to_numpy(data.GetPoints().GetData())
    cells = []
    for c in range(data.GetNumberOfCells()):
        ids = data.GetCell(c).GetPointIds()
        cells.append(points[[ids.GetId(k) for k in range(ids.GetNumberOfIds())]])
    return cells


def inside(polygon, normal, points):  # the points' projections on the polygon's plane are inside it (convex, CCW)
    n = len(polygon)
    return all((np.cross(polygon[(k + 1) % n] - polygon[k], points - polygon[k]) @ normal >= -TOL).all()
               for k in range(n))


scene = series("scene.pvd")
times = sorted({t for t, _, _ in scene})
assert len(times) == 3, f"expected frames at 0, 0.1 and 0.2 ms, got {times}"
for stem, expected in ARRAYS.items():
    part = series(stem + ".pvd")
    assert [t for t, _, _ in part] == times, f"{stem}.pvd times {[t for t, _, _ in part]} != scene.pvd's {times}"
    assert all(p == 0 and f.startswith(stem + "_") for _, f, p in part), f"{stem}.pvd holds other parts: {part}"
    assert [f for _, f, _ in part] == [f for _, f, _ in scene if f.startswith(stem + "_")]
    for _, f, _ in part:
        data = read(os.path.join(out, f))
        cd = data.GetCellData()
        names = {cd.GetArrayName(k) for k in range(cd.GetNumberOfArrays())}
        assert expected <= names, f"{f}: arrays {names}, expected {expected}"

gravity = read(os.path.join(out, series("bodies.pvd")[0][1])).GetFieldData().GetArray("gravity")
assert gravity is not None and gravity.GetTuple3(0) == (0.0, 0.0, -9.807), "bodies: no gravity field (-9.807 z)"

worst = 0.0
for (_, body_file, _), (_, driver_file, _) in zip(series("bodies.pvd"), series("drivers.pvd")):
    body_points = vtk_to_numpy(read(os.path.join(out, body_file)).GetPoints().GetData())
    drivers = read(os.path.join(out, driver_file))
    names = drivers.GetFieldData().GetAbstractArray("driver_names")
    walls = {names.GetValue(k): polygon for k, polygon in enumerate(polygons(drivers))}
    assert sorted(walls) == sorted(PLANES), f"{driver_file}: walls {sorted(walls)}"
    top = max(p[2] for p in walls["left"])
    assert top > body_points[:, 2].max(), "the walls are lower than the highest body at the start"
    for name, polygon in walls.items():
        point, normal = (np.array(v, float) for v in PLANES[name])
        assert len(polygon) == 4, f"{name}: {len(polygon)} corners"
        # The box's own corners: the floor is [-a, a]^2, each side runs from the floor to the top.
        lo, hi = np.where(normal != 0, point, -HALF), np.where(normal != 0, point, HALF)
        if name != "floor":
            lo[2], hi[2] = 0.0, top
        for corner in polygon:
            worst = max(worst, np.max(np.minimum(np.abs(corner - lo), np.abs(corner - hi))))
        for other, (q, m) in PLANES.items():  # no wall crosses another
            assert all(np.dot(c - np.array(q, float), m) >= -TOL for c in polygon), f"{name} crosses {other}"
        # Every body, at every frame, projects inside every wall.
        assert inside(polygon, normal, body_points), f"{driver_file}: a body is outside {name}"
assert worst <= TOL, f"a wall corner is {worst} m off the box's corner"
print(f"{len(scene)} datasets over {len(times)} frames; wall corners within {worst:.1e} m of the box's: ok")
