#!/usr/bin/env bash
# polydem plot on a tiny run: one non-empty PNG per CSV, each titled for what its CSV holds
# (the title read back from the PNG's own text chunk, and from plots.txt).
# usage: plot.sh PATH/TO/polydem
set -euo pipefail
source "$(dirname "$0")/script_lib.bash" "$1"
# drop.yaml with a flow probe: the mass of the bodies that fell below 10 cm.
sed "s|../../shapes|$here/../../shapes|" "$here/drop.yaml" > "$tmp/scene.yaml"
printf '  probes:\n    - flow: {name: below, point: [0, 0, 0.1], normal: [0, 0, -1]}\n' >> "$tmp/scene.yaml"
"$polydem" run "$tmp/scene.yaml" --until 0.02 --out "$tmp/out" 2> "$tmp/log" || { cat "$tmp/log"; fail "run"; }
"$polydem" plot "$tmp/out" -o "$tmp/plots" > "$tmp/plot.log" 2>&1 || { cat "$tmp/plot.log"; fail "plot"; }
set +e; "$polydem" plot "$tmp/nothere" > /dev/null 2> "$tmp/err"; code=$?; set -e
[ "$code" -eq 1 ] && grep -q "nothere" "$tmp/err" || fail "plot of a missing folder: exit $code, $(cat "$tmp/err")"

/usr/bin/python3 - "$tmp/out" "$tmp/plots" <<'PY'
import os, struct, sys, zlib
out, plots = sys.argv[1], sys.argv[2]
expected = {"energy": "Energy budget", "below": "Flow probe below: discharged mass and rate"}
for wall in ("floor", "left", "right"):
    expected["driver_" + wall] = f"Driver {wall}: force"
csvs = sorted(f[:-4] for f in os.listdir(out) if f.endswith(".csv"))
assert csvs == sorted(expected), f"the run wrote {csvs}, the test expects {sorted(expected)}"

def png_text(path):
    """The tEXt chunks of a PNG, and its width and height."""
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", f"{path}: not a PNG"
    text, pos, size = {}, 8, None
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        assert zlib.crc32(kind + body) == struct.unpack(">I", data[pos + 8 + n:pos + 12 + n])[0], f"{path}: bad CRC"
        if kind == b"IHDR":
            size = struct.unpack(">II", body[:8])
        if kind == b"tEXt":
            key, value = body.split(b"\0", 1)
            text[key.decode("latin-1")] = value.decode("latin-1")
        pos += 12 + n
    return text, size

listing = dict(line.rstrip("\n").split("\t") for line in open(os.path.join(plots, "plots.txt")))
for name, title in expected.items():
    png = os.path.join(plots, name + ".png")
    assert os.path.getsize(png) > 10000, f"{png}: {os.path.getsize(png)} bytes"
    text, (w, h) = png_text(png)
    assert text.get("Title") == title, f"{png}: title {text.get('Title')!r}, expected {title!r}"
    assert listing[name + ".png"] == title, f"plots.txt: {listing.get(name + '.png')!r}"
    assert w >= 400 and h >= 300, f"{png}: {w} x {h}"
print(f"{len(expected)} plots with their titles: ok")
PY
