#!/usr/bin/env bash
# samples/silo/beverloo_fit.py on made-up runs that follow Beverloo's law with C = 0.5 and
# k = 1.4 exactly: the fit gives them back, and --plot draws the PNG.
# usage: beverloo.sh PATH/TO/polydem
set -euo pipefail
polydem=$1
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
/usr/bin/python3 - "$tmp" "$polydem" "$here/../../samples/silo/beverloo_fit.py" <<'PY'
import math, os, re, subprocess, sys
tmp, polydem, fit = sys.argv[1:]
rho_b, g, c, k = 800.0, 9.807, 0.5, 1.4
d = float(re.search(r"d = ([0-9.]+) mm", subprocess.run(
    ["/usr/bin/python3", fit, "--polydem", polydem, "/nonexistent/D50"], capture_output=True, text=True).stdout).group(1)) / 1000
folders = []
for mm in (45, 50, 55, 60):
    w = c * rho_b * math.sqrt(g) * (mm / 1000 - k * d) ** 2.5  # kg/s
    folder = os.path.join(tmp, f"D{mm}")
    os.makedirs(folder)
    times = [0.005 * n for n in range(300)]
    def write(name, mass):
        with open(os.path.join(folder, name), "w") as f:
            f.write("time,mass,count,rate\n")
            f.writelines(f"{t},{mass(t)},0,0\n" for t in times)
    write("flow.csv", lambda t: w * max(t - 0.35, 0.0))  # the fill is 10 kg: never half out
    write("all.csv", lambda t: 10.0)
    write("below_2cm.csv", lambda t: 1.0)
    write("below_6cm.csv", lambda t: 1.0 + rho_b * math.pi * 0.06 ** 2 * 0.04)
    folders.append(folder)
png = os.path.join(tmp, "fit.png")
out = subprocess.run(["/usr/bin/python3", fit, "--polydem", polydem, "--plot", png, *folders],
                     check=True, capture_output=True, text=True).stdout
got_c, got_k = (float(v) for v in re.search(r"C = ([0-9.]+), k = ([0-9.]+)", out).groups())
assert abs(got_c - c) < 1e-3 and abs(got_k - k) < 1e-2, out
assert os.path.getsize(png) > 10000, f"{png}: {os.path.getsize(png)} bytes"
print(f"C = {got_c}, k = {got_k} recovered; fit.png {os.path.getsize(png)} bytes: ok")
PY
