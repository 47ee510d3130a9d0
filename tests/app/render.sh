#!/usr/bin/env bash
# polydem render on a tiny run, headless: a PNG of the asked size where the bodies' colour
# covers a stated share of the picture (the walls between the camera and them are cut away),
# the drivers show, and an MP4 of the frames.
# usage: render.sh PATH/TO/polydem
set -euo pipefail
source "$(dirname "$0")/script_lib.bash" "$1"
sed "s|../../shapes|$here/../../shapes|" "$here/drop.yaml" > "$tmp/scene.yaml"
"$polydem" run "$tmp/scene.yaml" --out "$tmp/out" 2> "$tmp/log" || { cat "$tmp/log"; fail "run"; }
"$polydem" render "$tmp/out" --color group --size 400x300 -o "$tmp/last.png" > "$tmp/render.log" 2>&1 ||
  { cat "$tmp/render.log"; fail "render"; }
"$polydem" render "$tmp/out" --every 2 --size 400x300 -o "$tmp/drop.mp4" > "$tmp/video.log" 2>&1 ||
  { cat "$tmp/video.log"; fail "render mp4"; }
[ "$(stat -c %s "$tmp/drop.mp4")" -gt 1000 ] || fail "drop.mp4 is $(stat -c %s "$tmp/drop.mp4") bytes"
set +e; "$polydem" render "$tmp/out" -o "$tmp/x.bmp" > /dev/null 2> "$tmp/err"; code=$?; set -e
[ "$code" -eq 1 ] && grep -q "x.bmp" "$tmp/err" || fail "render to .bmp: exit $code, $(cat "$tmp/err")"

# A drawing that aborts on its X connection (VTK's "bad X server connection") is tried on
# three display numbers, then reported with exit 2, never a raw abort.
printf '#!/bin/sh\nkill -ABRT $$\n' > "$tmp/abort.sh" && chmod +x "$tmp/abort.sh"
set +e; env -u DISPLAY POLYDEM_PYTHON="$tmp/abort.sh" "$polydem" render "$tmp/out" -o "$tmp/y.png" > /dev/null 2> "$tmp/err"
code=$?; set -e
[ "$code" -eq 2 ] && [ "$(grep -c "aborted (try" "$tmp/err")" -eq 3 ] || fail "aborting drawing: exit $code, $(cat "$tmp/err")"

/usr/bin/python3 - "$tmp/last.png" <<'PY'
import sys
import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader
reader = vtkPNGReader()
reader.SetFileName(sys.argv[1])
reader.Update()
image = reader.GetOutput()
w, h, _ = image.GetDimensions()
assert (w, h) == (400, 300), f"{w} x {h}, asked 400 x 300"
rgb = vtk_to_numpy(image.GetPointData().GetScalars())[:, :3].reshape(h, w, 3).astype(float) / 255
picture = rgb[:, : int(0.84 * w)]  # the colour bar is on the right
lo, hi = picture.min(axis=2), picture.max(axis=2)
saturation = np.where(hi > 0, (hi - lo) / np.maximum(hi, 1e-9), 0)
blue = (saturation > 0.5) & (picture[..., 2] == hi)  # the one group's blue, shaded
grey = (saturation < 0.25) & (hi < 0.9) & (hi > 0.5)  # the translucent walls over the white
body_share, wall_share = blue.mean(), grey.mean()
print(f"bodies cover {body_share:.1%} of the picture, walls {wall_share:.1%}")
# 41 bodies framed by the camera, falling: their blue covers 8.4% (measured); with a wall
# drawn opaque in front of them it would be near 0.
assert body_share > 0.04, f"the bodies cover {body_share:.1%} of the picture"
assert wall_share > 0.02, f"the walls cover {wall_share:.1%}"
PY
