"""Reads a polydem output folder with VTK's own readers and checks it is complete and sane.
usage: check_output.py OUTPUT_DIR BODY_COUNT"""
import csv
import os
import sys
import xml.etree.ElementTree as ET

try:
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
except ImportError:
    sys.exit("python3-vtk9 is missing: apt-get install python3-vtk9")

out, bodies = sys.argv[1], int(sys.argv[2])
datasets = ET.parse(os.path.join(out, "scene.pvd")).getroot().find("Collection").findall("DataSet")
times = sorted({float(d.get("timestep")) for d in datasets})
assert len(times) >= 4, f"expected frames at 0, 10, 20, 30, 40 ms, got {times}"
for d in datasets:
    path = os.path.join(out, d.get("file"))
    reader = vtk.vtkXMLUnstructuredGridReader() if path.endswith(".vtu") else vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    assert data.GetNumberOfPoints() > 0 or "contacts" in path, f"{path}: empty"
    if os.path.basename(path).startswith("bodies"):
        ids = vtk_to_numpy(data.GetCellData().GetArray("id"))
        assert len(set(ids.tolist())) == bodies, f"{path}: {len(set(ids.tolist()))} bodies, expected {bodies}"
        z = vtk_to_numpy(data.GetPoints().GetData())[:, 2]
        assert z.min() > -1e-3, f"{path}: a body went through the floor (z = {z.min()})"
rows = list(csv.DictReader(open(os.path.join(out, "energy.csv"))))
assert len(rows) >= 40, f"energy.csv has {len(rows)} rows"
assert float(rows[-1]["contacts"]) > 0, "no contacts at the end of the drop"
print(f"{len(datasets)} datasets over {len(times)} frames, {len(rows)} energy rows: ok")
