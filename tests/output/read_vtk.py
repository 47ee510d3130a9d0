#!/usr/bin/env python3
"""Reads a polydem .vtu/.vtp/.pvd with VTK's own XML readers and prints it as JSON.

Usage: /usr/bin/python3 read_vtk.py FILE
Exit codes: 0 ok, 2 VTK reported an error, 3 the vtk module is missing.
"""
import json
import os
import sys
import xml.etree.ElementTree as ET

try:  # the three modules needed, not all of `vtk`: the tests start this script often
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkCommonCore import vtkStringArray
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLUnstructuredGridReader
except ImportError as e:
    print(f"cannot import vtk in {sys.executable} ({e}): apt-get install python3-vtk9", file=sys.stderr)
    sys.exit(3)


class ErrorCatcher:
    """Collects VTK error events, which VTK otherwise only prints."""

    def __init__(self):
        self.messages = []

    def __call__(self, caller, event, data=None):
        self.messages.append(str(data) if data else event)


def read_dataset(path):
    reader = vtkXMLUnstructuredGridReader() if path.endswith(".vtu") else vtkXMLPolyDataReader()
    catcher = ErrorCatcher()
    reader.AddObserver("ErrorEvent", catcher)
    reader.GetExecutive().AddObserver("ErrorEvent", catcher)
    reader.SetFileName(path)
    reader.Update()
    if catcher.messages or reader.GetErrorCode():
        print(f"VTK could not read {path}: {catcher.messages}", file=sys.stderr)
        sys.exit(2)
    return reader.GetOutput()


def array_json(array):
    if isinstance(array, vtkStringArray):
        return {"type": "String", "values": [array.GetValue(k) for k in range(array.GetNumberOfValues())]}
    values = vtk_to_numpy(array).reshape(-1).tolist()
    return {"type": array.GetDataTypeAsString(), "components": array.GetNumberOfComponents(), "values": values}


def dataset_json(data):
    cells = []
    for c in range(data.GetNumberOfCells()):
        ids = data.GetCell(c).GetPointIds()
        cells.append([ids.GetId(k) for k in range(ids.GetNumberOfIds())])
    points = data.GetPoints()
    cd, fd = data.GetCellData(), data.GetFieldData()
    return {
        "n_points": data.GetNumberOfPoints(),
        "n_cells": data.GetNumberOfCells(),
        "points": vtk_to_numpy(points.GetData()).tolist() if points else [],
        "bounds": list(data.GetBounds()),
        "cells": cells,
        "cell_types": [data.GetCellType(c) for c in range(data.GetNumberOfCells())],
        "cell_data": {cd.GetArrayName(k): array_json(cd.GetAbstractArray(k)) for k in range(cd.GetNumberOfArrays())},
        "field_data": {fd.GetArrayName(k): array_json(fd.GetAbstractArray(k)) for k in range(fd.GetNumberOfArrays())},
    }


def pvd_json(path):
    root = ET.parse(path).getroot()
    folder = os.path.dirname(path)
    datasets = []
    for d in root.iter("DataSet"):
        data = read_dataset(os.path.join(folder, d.get("file")))
        datasets.append({"timestep": float(d.get("timestep")), "part": int(d.get("part")), "file": d.get("file"),
                         "n_points": data.GetNumberOfPoints(), "n_cells": data.GetNumberOfCells()})
    return {"type": root.get("type"), "datasets": datasets}


def main():
    path = sys.argv[1]
    result = pvd_json(path) if path.endswith(".pvd") else dataset_json(read_dataset(path))
    print(json.dumps(result))


if __name__ == "__main__":
    main()
