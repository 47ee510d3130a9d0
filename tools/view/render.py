#!/usr/bin/python3
"""polydem render: pictures of a run's bodies and drivers, headless, with VTK.

usage: render.py OUT_DIR FILE.png|.mp4|.gif [--time T | --every K] [--color velocity|group|id|radius]
                 [--size WxH]
Reads bodies.pvd and drivers.pvd (or scene.pvd). The camera looks from the side with gravity
down (the `gravity` field of the bodies' files, else -z), along the horizontal axis in which
the bodies are thinnest, turned 25 deg about the vertical and raised 15 deg; it frames the bodies
(parallel projection). Drivers are drawn translucent, and those nearer the camera than the
middle of the bodies are cut away, so that no wall stands between the camera and the bodies.
A .png is the frame at time T (default: the last); a video takes every K-th frame (ffmpeg).
Exit codes: 0 ok, 1 bad input, 2 rendering failed, 3 VTK missing.
"""
import argparse
import math
import os
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

try:
    import numpy as np
    import vtkmodules.vtkInteractionStyle  # noqa: F401 (registers the default interactor classes)
    import vtkmodules.vtkRenderingFreeType  # noqa: F401 (text)
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the GL back end)
    from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
    from vtkmodules.vtkCommonCore import vtkLookupTable
    from vtkmodules.vtkFiltersCore import vtkThreshold
    from vtkmodules.vtkIOImage import vtkPNGWriter
    from vtkmodules.vtkIOXML import (vtkXMLPolyDataReader, vtkXMLPUnstructuredGridReader,
                                     vtkXMLUnstructuredGridReader)
    from vtkmodules.vtkRenderingAnnotation import vtkScalarBarActor
    from vtkmodules.vtkRenderingCore import (vtkActor, vtkDataSetMapper, vtkRenderer, vtkRenderWindow, vtkTextActor,
                                             vtkWindowToImageFilter)
except ImportError as e:
    print(f"polydem render: cannot import VTK in {sys.executable} ({e}): apt-get install python3-vtk9", file=sys.stderr)
    sys.exit(3)

TURN, RAISE = math.radians(25), math.radians(15)  # camera: about the vertical, above the horizontal
MARGIN = 1.08          # the frame is this much wider than the bodies
DRIVER_OPACITY = 0.3
DRIVER_RGB = (0.55, 0.6, 0.7)
BACKGROUND = (1.0, 1.0, 1.0)
COLORS = ("velocity", "group", "id", "radius")


def fail(message, code=1):
    print(f"polydem render: {message}", file=sys.stderr)
    sys.exit(code)


def series(out, stem):
    """[(time, path)] of the STEM files, from STEM.pvd or else scene.pvd."""
    own = os.path.join(out, stem + ".pvd")
    path = own if os.path.exists(own) else os.path.join(out, "scene.pvd")
    if not os.path.exists(path):
        return []
    sets = ET.parse(path).getroot().iter("DataSet")
    return [(float(d.get("timestep")), os.path.join(out, d.get("file"))) for d in sets
            if os.path.basename(d.get("file")).startswith(stem + "_")]


def read(path):
    readers = {".vtu": vtkXMLUnstructuredGridReader, ".pvtu": vtkXMLPUnstructuredGridReader}  # .pvtu: a run's ranks
    reader = readers.get(os.path.splitext(path)[1], vtkXMLPolyDataReader)()
    reader.SetFileName(path)
    reader.Update()
    if reader.GetErrorCode():
        fail(f"VTK could not read {path}", 2)
    return reader.GetOutput()


def gravity_of(bodies):
    g = bodies.GetFieldData().GetArray("gravity")
    if g is not None and g.GetNumberOfTuples() == 1:
        v = np.array(g.GetTuple3(0))
        if np.linalg.norm(v) > 0:
            return v / np.linalg.norm(v)
    return np.array([0.0, 0.0, -1.0])


def camera_axes(bodies, down):
    """Unit vectors (view direction, up, right): a side view with `down` pointing down the picture."""
    up = -down
    points = vtk_to_numpy(bodies.GetPoints().GetData())
    helper = np.eye(3)[np.argmin(np.abs(np.eye(3) @ up))]  # the world axis least along up
    a = helper - helper.dot(up) * up
    a /= np.linalg.norm(a)
    b = np.cross(up, a)
    # Look along the horizontal direction in which the bodies are thinnest: the wide side faces us.
    look = a if np.ptp(points @ a) <= np.ptp(points @ b) else b
    side = np.cross(look, up)
    look = math.cos(TURN) * look + math.sin(TURN) * side
    view = math.cos(RAISE) * look - math.sin(RAISE) * up
    right = np.cross(view, up)
    right /= np.linalg.norm(right)
    return view, np.cross(right, view), right


def colour_array(bodies, name):
    cd = bodies.GetCellData()
    if name == "velocity":
        v = vtk_to_numpy(cd.GetArray("velocity"))
        values, title = np.linalg.norm(v, axis=1), "speed (m/s)"
    else:
        array = cd.GetArray(name)
        if array is None:
            fail(f"the bodies have no '{name}' array (choose from {', '.join(COLORS)})")
        values, title = vtk_to_numpy(array).astype(float), name
    vtk_values = numpy_to_vtk(values, deep=True)
    vtk_values.SetName("colour")
    cd.AddArray(vtk_values)
    cd.SetActiveScalars("colour")
    return values, title


def lookup_table(values, categorical):
    table = vtkLookupTable()
    lo, hi = values.min(), values.max()
    table.SetTableRange(lo, hi if hi > lo else lo + 1)
    if categorical:  # groups: one saturated hue each, named in the bar
        groups = np.unique(values)
        table.IndexedLookupOn()
        table.SetNumberOfTableValues(len(groups))
        for k, v in enumerate(groups):
            table.SetAnnotation(float(v), f"{int(v)}")
            table.SetTableValue(k, *hue_rgb((0.6 + 0.38 * k) % 1.0), 1.0)
    else:  # blue (slow) to red (fast)
        table.SetHueRange(0.667, 0.0)
        table.SetSaturationRange(0.9, 0.9)
        table.SetValueRange(0.95, 0.95)
    table.Build()
    return table


def hue_rgb(h):
    import colorsys
    return colorsys.hsv_to_rgb(h, 0.85, 0.9)


def behind_middle(drivers, middle, view):
    """The driver cells whose centres are not nearer the camera than the middle of the bodies."""
    cd = drivers.GetCellData()
    depth = np.empty(drivers.GetNumberOfCells())
    for c in range(drivers.GetNumberOfCells()):
        ids = drivers.GetCell(c).GetPointIds()
        corners = np.array([drivers.GetPoint(ids.GetId(k)) for k in range(ids.GetNumberOfIds())])
        depth[c] = (corners.mean(axis=0) - middle) @ view
    array = numpy_to_vtk(depth, deep=True)
    array.SetName("depth")
    cd.AddArray(array)
    keep = vtkThreshold()
    keep.SetInputData(drivers)
    keep.SetInputArrayToProcess(0, 0, 0, 1, "depth")  # 1: cell data
    keep.SetLowerThreshold(-1e-9 * max(1.0, np.abs(depth).max()))
    keep.SetUpperThreshold(1e300)
    keep.SetThresholdFunction(vtkThreshold.THRESHOLD_BETWEEN)
    keep.Update()
    return keep.GetOutput()


def render_frame(time, bodies_path, drivers_path, args, png):
    bodies = read(bodies_path)
    if bodies.GetNumberOfCells() == 0:
        fail(f"{bodies_path} holds no body", 1)
    view, up, right = camera_axes(bodies, gravity_of(bodies))
    lo_hi = np.array(bodies.GetBounds()).reshape(3, 2)
    middle = lo_hi.mean(axis=1)
    values, title = colour_array(bodies, args.color)
    categorical = args.color == "group"
    renderer = vtkRenderer()
    renderer.SetBackground(*BACKGROUND)

    mapper = vtkDataSetMapper()
    mapper.SetInputData(bodies)
    mapper.SetScalarModeToUseCellData()
    mapper.SetLookupTable(lookup_table(values, categorical))
    mapper.SetScalarRange(values.min(), values.max() if values.max() > values.min() else values.min() + 1)
    actor = vtkActor()
    actor.SetMapper(mapper)
    renderer.AddActor(actor)

    if drivers_path:
        drivers = behind_middle(read(drivers_path), middle, view)
        if drivers.GetNumberOfCells() > 0:
            dmapper = vtkDataSetMapper()
            dmapper.SetInputData(drivers)
            dmapper.ScalarVisibilityOff()
            dactor = vtkActor()
            dactor.SetMapper(dmapper)
            dactor.GetProperty().SetColor(*DRIVER_RGB)
            dactor.GetProperty().SetOpacity(DRIVER_OPACITY)
            renderer.AddActor(dactor)

    bar = vtkScalarBarActor()
    bar.SetLookupTable(mapper.GetLookupTable())
    bar.SetTitle(title)
    bar.SetNumberOfLabels(4)
    bar.SetLabelFormat("%.2g")
    bar.SetPosition(0.83, 0.1)
    bar.SetWidth(0.13)
    bar.SetHeight(0.8)
    bar.UnconstrainedFontSizeOn()
    for text, size in ((bar.GetTitleTextProperty(), 13), (bar.GetLabelTextProperty(), 12),
                       (bar.GetAnnotationTextProperty(), 12)):
        text.SetColor(0.1, 0.1, 0.1)
        text.SetFontSize(size)
        text.ShadowOff()
        text.ItalicOff()
        text.BoldOff()
    renderer.AddViewProp(bar)

    label = vtkTextActor()
    label.SetInput(f"t = {time:.4g} s")
    label.GetTextProperty().SetColor(0.1, 0.1, 0.1)
    label.GetTextProperty().SetFontSize(max(12, args.height // 22))
    label.SetPosition(10, 10)
    renderer.AddViewProp(label)

    # Parallel projection framing the bodies' box, in the left 85% of the picture (the bar is right).
    corners = np.array([[x, y, z] for x in lo_hi[0] for y in lo_hi[1] for z in lo_hi[2]]) - middle
    half_h = np.abs(corners @ up).max() * MARGIN
    half_w = np.abs(corners @ right).max() * MARGIN
    aspect = 0.85 * args.width / args.height
    scale = max(half_h, half_w / aspect)  # m, half the picture's height
    focus = middle + right * 0.075 * 2 * scale * args.width / args.height  # the bodies in the middle of the left 85%
    distance = 4 * np.linalg.norm(lo_hi[:, 1] - lo_hi[:, 0]) + 1e-3
    camera = renderer.GetActiveCamera()
    camera.ParallelProjectionOn()
    camera.SetFocalPoint(*focus)
    camera.SetPosition(*(focus - distance * view))
    camera.SetViewUp(*up)
    camera.SetParallelScale(scale)
    renderer.ResetCameraClippingRange()

    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(args.width, args.height)
    window.AddRenderer(renderer)
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    writer = vtkPNGWriter()
    writer.SetFileName(png)
    writer.SetCompressionLevel(9)  # smaller files, same pixels
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    window.Finalize()


def nearest(frames, time):
    return min(frames, key=lambda f: abs(f[0] - time))


def main():
    parser = argparse.ArgumentParser(prog="polydem render")
    parser.add_argument("out")
    parser.add_argument("file")
    which = parser.add_mutually_exclusive_group()
    which.add_argument("--time", type=float)
    which.add_argument("--every", type=int)
    parser.add_argument("--color", default="velocity", choices=COLORS)
    parser.add_argument("--size", default="800x600")
    args = parser.parse_args()
    try:
        args.width, args.height = (int(v) for v in args.size.lower().split("x"))
    except ValueError:
        fail(f"--size {args.size}: expected WIDTHxHEIGHT in pixels, e.g. 800x600")
    bodies = series(args.out, "bodies")
    if not bodies:
        fail(f"{args.out}: no bodies.pvd or scene.pvd with bodies (was vtk_every set?)")
    drivers = dict(series(args.out, "drivers"))
    ext = os.path.splitext(args.file)[1].lower()
    if ext == ".png":
        if args.every:
            fail("--every makes a video: give -o FILE.mp4 or FILE.gif")
        time, path = nearest(bodies, args.time if args.time is not None else bodies[-1][0])
        render_frame(time, path, drivers.get(time), args, args.file)
        print(f"{args.file}: t = {time:.6g} s")
    elif ext in (".mp4", ".gif"):
        if args.time is not None:
            fail("--time picks one picture: give -o FILE.png")
        if not shutil.which("ffmpeg"):
            fail("ffmpeg is missing: apt-get install ffmpeg", 2)
        with tempfile.TemporaryDirectory() as tmp:
            chosen = bodies[::args.every or 1]
            for k, (time, path) in enumerate(chosen):
                render_frame(time, path, drivers.get(time), args, os.path.join(tmp, f"frame_{k:06d}.png"))
            codec = ["-pix_fmt", "yuv420p", "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2"] if ext == ".mp4" else []
            done = subprocess.run(["ffmpeg", "-y", "-loglevel", "error", "-framerate", "10", "-i",
                                   os.path.join(tmp, "frame_%06d.png"), *codec, args.file])
            if done.returncode != 0:
                fail(f"ffmpeg could not write {args.file}", 2)
        print(f"{args.file}: {len(chosen)} frames")
    else:
        fail(f"-o {args.file}: expected a .png, .mp4 or .gif")


if __name__ == "__main__":
    main()
