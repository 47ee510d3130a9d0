#!/usr/bin/python3
"""Fill level of the drum from bodies VTU frames: for each frame, the highest body centre per
column one grain (8.5 mm) wide across the drum (x), a least-squares line through the columns
of the central 60% of the surface (as the repose_angle probe does), and the line's height at
the axis (x = 0); then the mean and std over the frames. A bed filling half the drum has its
grains' tops (the top centres plus half a grain) at the axis.

Usage: fill_level.py out/bodies_000020.vtu out/bodies_000021.vtu ...
"""
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

GRAIN = 0.0085  # m, mean equivalent diameter of the mix (README)


def centres(path):
    """Mean of each body's vertices (cells are grouped by their `id`)."""
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    points = vtk_to_numpy(grid.GetPoints().GetData())
    ids = vtk_to_numpy(grid.GetCellData().GetArray("id"))
    members = {}
    for c in range(grid.GetNumberOfCells()):
        cell = grid.GetCell(c)
        members.setdefault(int(ids[c]), set()).update(cell.GetPointId(k) for k in range(cell.GetNumberOfPoints()))
    return np.array([points[sorted(members[b])].mean(axis=0) for b in sorted(members)])


def surface(path):
    c = centres(path)
    column = np.floor(c[:, 0] / GRAIN).astype(int)
    keys = sorted(set(column))
    x = np.array([(k + 0.5) * GRAIN for k in keys])
    top = np.array([c[column == k, 2].max() for k in keys])
    central = np.abs(x - 0.5 * (x.min() + x.max())) <= 0.3 * (x.max() - x.min())
    slope, height = np.polyfit(x[central], top[central], 1)
    return np.degrees(np.arctan(abs(slope))), height


rows = np.array([surface(p) for p in sys.argv[1:]])
for path, (angle, height) in zip(sys.argv[1:], rows):
    print(f"{path}: angle {angle:.1f} deg, top centres at the axis {height * 1000:+.1f} mm")
print(f"mean over {len(rows)} frames: angle {rows[:, 0].mean():.1f} deg, top centres at the axis "
      f"{rows[:, 1].mean() * 1000:+.1f} mm (std {rows[:, 1].std() * 1000:.1f}), grains' tops "
      f"{(rows[:, 1].mean() + GRAIN / 2) * 1000:+.1f} mm")
