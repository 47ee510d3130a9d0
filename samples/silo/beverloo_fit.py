#!/usr/bin/python3
"""Steady discharge rates of the silo runs and the Beverloo fit W = C rho_b sqrt(g) (D - k d)^(5/2).

Usage: beverloo_fit.py [--polydem build/polydem] [--plot FIT.png] out/D40 out/D50 out/D60 ...
Each folder is the output of one orifice size, named D<mm>. From its probes:
- W: least-squares slope of flow.csv's discharged mass over time, from OPEN + SKIP until the
  discharged mass reaches FRACTION of the fill (all.csv) or the run ends (steady regime:
  after the start-up transient, while the fill is still well above the orifice);
- rho_b: mass of the bodies whose centres lie between z = 2 cm and 6 cm when the gate opens
  (below_6cm.csv - below_2cm.csv) over the slab's volume pi R^2 0.04 m.
d is the mean equivalent-volume diameter of the fill, (6 V / pi)^(1/3) averaged over the mix
(volumes from `polydem shape info --json`). The fit is linear in W^(2/5) = a (D - k d) with
a = (C rho_b sqrt(g))^(2/5). --plot draws the rates and the fitted law against D.
"""
import argparse
import csv
import json
import math
import os
import re
import subprocess

import numpy as np

OPEN = 0.3          # s, gate removal (scene.yaml)
SKIP = 0.2          # s, start-up transient left out (the rate still grows ~30% over 0.1-0.3 s)
FRACTION = 0.5      # of the fill discharged: beyond it the fill is too shallow for a steady rate
RADIUS = 0.06       # m, silo
SLAB = (0.02, 0.06)  # m, heights of the bulk-density slab
G = 9.807           # m/s^2
MIX = {"dodecahedron": 0.4, "icosahedron": 0.4, "rock1": 0.2}  # number fractions (scene.yaml)
LIBRARIES = ["shapes/platonic.shp", "shapes/rocks.shp"]


def read(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def at_open(series):
    """The mass of a probe at the last row before the gate opens."""
    k = np.searchsorted(series["time"], OPEN + 1e-9) - 1
    return series["mass"][k]


def steady_rate(folder):
    flow = read(os.path.join(folder, "flow.csv"))
    total = read(os.path.join(folder, "all.csv"))["mass"][0]
    t, m = flow["time"], flow["mass"]
    keep = (t >= OPEN + SKIP) & (m <= FRACTION * total)
    if keep.sum() < 5:
        raise SystemExit(f"{folder}: fewer than 5 rows in the steady window (run longer?)")
    slope = np.polyfit(t[keep], m[keep], 1)[0]
    half = len(t[keep]) // 2  # the two halves of the window: how steady the rate is
    halves = [np.polyfit(t[keep][s], m[keep][s], 1)[0] for s in (slice(0, half + 1), slice(half, None))]
    return slope, t[keep][0], t[keep][-1], halves


def bulk_density(folder):
    low = at_open(read(os.path.join(folder, "below_2cm.csv")))
    high = at_open(read(os.path.join(folder, "below_6cm.csv")))
    return (high - low) / (math.pi * RADIUS ** 2 * (SLAB[1] - SLAB[0]))


def equivalent_diameter(polydem, root):
    volumes = {}
    for lib in LIBRARIES:
        info = json.loads(subprocess.run([polydem, "shape", "info", os.path.join(root, lib), "--json"],
                                         check=True, capture_output=True, text=True).stdout)
        volumes.update({s["name"]: s["volume"] for s in info})
    return sum(f * (6 * volumes[n] / math.pi) ** (1 / 3) for n, f in MIX.items())


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.normpath(os.path.join(here, "..", ".."))
    parser = argparse.ArgumentParser()
    parser.add_argument("--polydem", default=os.path.join(root, "build", "polydem"))
    parser.add_argument("--plot", help="PNG of the rates and the fit against the orifice size")
    parser.add_argument("folders", nargs="+")
    args = parser.parse_args()
    d = equivalent_diameter(args.polydem, root)
    sizes, rates, densities = [], [], []
    print(f"d = {d * 1000:.2f} mm (mean equivalent-volume diameter)")
    print("D (mm)  D/d   W (kg/s)  window (s)   halves (kg/s)    rho_b (kg/m^3)")
    for folder in args.folders:
        size = int(re.search(r"D(\d+)", os.path.basename(os.path.normpath(folder))).group(1)) / 1000
        w, t0, t1, halves = steady_rate(folder)
        rho = bulk_density(folder)
        sizes.append(size), rates.append(w), densities.append(rho)
        print(f"{size * 1000:6.0f}  {size / d:4.2f}  {w:8.4f}  {t0:.3f}-{t1:.3f}  {halves[0]:.3f} {halves[1]:.3f}  {rho:8.1f}")
    rho_b = float(np.mean(densities))
    a, b = np.polyfit(sizes, np.array(rates) ** 0.4, 1)
    c, k = a ** 2.5 / (rho_b * math.sqrt(G)), -b / (a * d)
    print(f"rho_b = {rho_b:.0f} kg/m^3 (mean of the runs)")
    print(f"Beverloo fit: C = {c:.3f}, k = {k:.2f}")
    for size, w in zip(sizes, rates):
        model = c * rho_b * math.sqrt(G) * max(size - k * d, 0.0) ** 2.5
        print(f"  D = {size * 1000:.0f} mm: W = {w:.4f} kg/s, fit {model:.4f} kg/s")
    if args.plot:
        plot_fit(args.plot, sizes, rates, c, k, d, rho_b)


def plot_fit(path, sizes, rates, c, k, d, rho_b):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    title = "Beverloo fit of the discharge rates"
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    span = np.linspace(min(sizes) * 0.9, max(sizes) * 1.1, 100)
    ax.plot(np.array(sizes) * 1000, rates, "o", label="polydem (steady rate)")
    ax.plot(span * 1000, c * rho_b * math.sqrt(G) * np.maximum(span - k * d, 0.0) ** 2.5, "k--",
            label=f"W = C rho_b sqrt(g) (D - k d)^2.5, C = {c:.2f}, k = {k:.2f}")
    ax.set_xlabel("orifice diameter D (mm)")
    ax.set_ylabel("discharge rate W (kg/s)")
    ax.legend(fontsize=8)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=100, metadata={"Title": title})


if __name__ == "__main__":
    main()
