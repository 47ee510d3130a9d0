#!/usr/bin/env python3
"""Packing fraction of the settled rice bed from a bodies_NNNNNN.vtu.

Usage: /usr/bin/python3 samples/rice/packing.py out/bodies_000030.vtu GRAIN_VOLUME_M3
A grain's height is the middle of its drawn points' z range; the bed's top is the highest
grain; the fraction counts the grains whose middle lies in the band 5 mm over the floor to
5 mm under the top, over the box's 3 x 3 cm section times the band's height (grains cut by
a bound count by their middle: unbiased; the walls' looser layer is included).
"""
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader

reader = vtkXMLUnstructuredGridReader()
reader.SetFileName(sys.argv[1])
reader.Update()
grid = reader.GetOutput()
points = vtk_to_numpy(grid.GetPoints().GetData())
ids = vtk_to_numpy(grid.GetCellData().GetArray("id"))
offsets = vtk_to_numpy(grid.GetCells().GetOffsetsArray())
connectivity = vtk_to_numpy(grid.GetCells().GetConnectivityArray())
lo, hi = {}, {}
for c, body in enumerate(ids):
    z = points[connectivity[offsets[c]:offsets[c + 1]], 2]
    lo[body] = min(lo.get(body, np.inf), z.min())
    hi[body] = max(hi.get(body, -np.inf), z.max())
middle = np.array([(lo[b] + hi[b]) / 2 for b in lo])
top = middle.max()
low, high = 0.005, top - 0.005  # m, the band
inside = int(((middle >= low) & (middle < high)).sum())
fraction = inside * float(sys.argv[2]) / (0.03 * 0.03 * (high - low))
print(f"grains {len(middle)}, top {top * 1000:.1f} mm, {inside} in {low * 1000:.0f}-{high * 1000:.1f} mm: "
      f"packing fraction {fraction:.3f}")
