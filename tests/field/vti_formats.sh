#!/usr/bin/env bash
# The fluid grid reader on the files python vtk (ParaView's writer) produces: every encoding
# (ascii, inline base64, appended raw and base64), with and without zlib, UInt32 and UInt64
# headers, cell and point data. polydem reads each grid and writes it back as
# fluid_000000.vti; the arrays must come back bit for bit.
# usage: vti_formats.sh PATH/TO/polydem
set -euo pipefail
polydem=$1
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

/usr/bin/python3 - "$polydem" "$tmp" "$here/../../shapes/platonic.shp" <<'PY'
import subprocess, sys
import numpy as np
import vtk
from vtk.util.numpy_support import numpy_to_vtk, vtk_to_numpy

polydem, tmp, shapes = sys.argv[1:]
rng = np.random.default_rng(3)

def image(cell_data):
    img = vtk.vtkImageData()
    img.SetDimensions(5, 4, 3)
    img.SetOrigin(-0.02, -0.015, 0.0)
    img.SetSpacing(0.01, 0.01, 0.02)
    n = img.GetNumberOfCells() if cell_data else img.GetNumberOfPoints()
    data = img.GetCellData() if cell_data else img.GetPointData()
    arrays = {"U": rng.normal(size=(n, 3)), "p": rng.normal(size=n) * 1e3,
              "rho": 1000 + rng.random(n), "nu": 1e-6 * (1 + rng.random(n))}
    for name, a in arrays.items():
        v = numpy_to_vtk(a, deep=True)
        v.SetName(name)
        data.AddArray(v)
    return img, arrays

modes = [("ascii", None, False), ("binary", None, False), ("binary", "zlib", False),
         ("appended", None, False), ("appended", "zlib", False), ("appended", "zlib", True),
         ("appended", None, True)]
failures = 0
for k, (mode, comp, base64) in enumerate(modes):
    for cell_data in (True, False):
        for header64 in (False, True):
            img, arrays = image(cell_data)
            name = f"{tmp}/g{k}_{int(cell_data)}_{int(header64)}"
            w = vtk.vtkXMLImageDataWriter()
            w.SetFileName(name + ".vti")
            w.SetInputData(img)
            getattr(w, {"ascii": "SetDataModeToAscii", "binary": "SetDataModeToBinary",
                        "appended": "SetDataModeToAppended"}[mode])()
            if comp: w.SetCompressorTypeToZLib()
            else: w.SetCompressorTypeToNone()
            if mode == "appended":
                w.SetEncodeAppendedData(base64)
            if header64: w.SetHeaderTypeToUInt64()
            else: w.SetHeaderTypeToUInt32()
            w.Write()
            with open(name + ".yaml", "w") as f:
                f.write(f"""simulation: {{duration: 0.001, dt: 0.0001}}
shapes: [{shapes}]
bodies:
  - {{shape: sphere, position: [0, 0, 0.01]}}
forces:
  - contact_sphere: {{config: {{kn: 1.0e4, kt: 1.0e4, mu: 0.5, en: 0.5}}}}
  - fluid_field: {{file: {name}.vti}}
  - sphere_fluid_friction: {{cx: 1}}
  - pressure_force: {{}}
  - viscous_force: {{}}
output: {{vtk_every: 0.001}}
""")
            run = subprocess.run([polydem, "run", name + ".yaml", "--out", name, "--until", "0"],
                                 capture_output=True, text=True)
            label = f"{mode} {comp} base64={base64} cell={cell_data} uint64={header64}"
            if run.returncode != 0:
                print("FAIL", label, run.stderr.strip()); failures += 1; continue
            r = vtk.vtkXMLImageDataReader()
            r.SetFileName(name + "/fluid_000000.vti")
            r.Update()
            out = r.GetOutput()
            expected_origin = np.array(img.GetOrigin()) - (0 if cell_data else 0.5 * np.array(img.GetSpacing()))
            ok = np.allclose(out.GetOrigin(), expected_origin, rtol=0, atol=1e-15)
            for a, values in arrays.items():
                got = vtk_to_numpy(out.GetCellData().GetArray(a))
                ok = ok and got.shape == values.shape and np.array_equal(got, values)
            if not ok:
                print("FAIL", label, "arrays or origin differ"); failures += 1
            else:
                print("ok  ", label)
sys.exit(1 if failures else 0)
PY
