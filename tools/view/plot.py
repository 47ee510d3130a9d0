#!/usr/bin/python3
"""polydem plot: one PNG per CSV of a run's output folder, with matplotlib.

usage: plot.py OUT_DIR PNG_DIR
Each CSV is recognised by its columns: energy.csv (the energy budget and its balance residual),
driver_NAME.csv (force on the driver), flow probes (discharged mass and rate, with the rate
fitted over the steady part of the discharge), repose-angle probes, fluid.csv; any other CSV
gets its columns over time. Each PNG carries its title as PNG text metadata ("Title"), and
PNG_DIR/plots.txt lists "file<TAB>title" per plot.
Exit codes: 0 ok, 1 bad input (no folder, no CSV), 3 matplotlib missing.
"""
import csv
import os
import sys

try:
    import matplotlib
    matplotlib.use("Agg")  # no display needed
    import matplotlib.pyplot as plt
    import numpy as np
except ImportError as e:
    print(f"polydem plot: cannot import matplotlib in {sys.executable} ({e}): apt-get install python3-matplotlib",
          file=sys.stderr)
    sys.exit(3)

SIZE = (6.4, 4.0)  # inches at DPI: 640 x 400 pixels, tens of KB
DPI = 100


def read_csv(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    if len(rows) < 2:
        return rows[0] if rows else [], {}
    header = rows[0]
    data = np.array([[float(v) for v in r] for r in rows[1:] if len(r) == len(header)])
    return header, {name: data[:, k] for k, name in enumerate(header)}


def energy_plot(name, c):
    t = c["time"]
    source = c["gravity_work"] + c["driver_work"] + c.get("external_work", 0 * t)
    held = c["kinetic"] + c["rotational"] + c["elastic"] + c["dissipated"]
    source = source + held[0] - source[0]  # the energy at the first row counts as given
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=SIZE, gridspec_kw={"height_ratios": [3, 1]})
    for key in ("kinetic", "rotational", "elastic", "dissipated"):
        top.plot(t, c[key], label=key)
    top.plot(t, source, "k--", label="initial energy + work of gravity, drivers, fields")
    top.set_ylabel("energy (J)")
    top.legend(fontsize=7)
    scale = max(np.abs(source).max(), 1e-300)
    bottom.plot(t, (source - held) / scale, color="tab:red")
    bottom.set_ylabel("balance\nresidual / max")
    bottom.set_xlabel("time (s)")
    return fig, "Energy budget"


def driver_plot(name, c):
    t = c["time"]
    fig, ax = plt.subplots(figsize=SIZE)
    for key in ("fx", "fy", "fz"):
        ax.plot(t, c[key], label=key)
    ax.plot(t, np.sqrt(c["fx"] ** 2 + c["fy"] ** 2 + c["fz"] ** 2), "k", lw=0.8, label="|F|")
    ax.set_xlabel("time (s)")
    ax.set_ylabel("force of the particles (N)")
    ax.legend(fontsize=7)
    return fig, f"Driver {name[len('driver_'):]}: force"


def steady_rate(t, m):
    """kg/s, slope of the discharged mass while it climbs from 20% to 80% of its final gain."""
    gained = m - m[0]
    final = gained[-1]
    keep = (gained >= 0.2 * final) & (gained <= 0.8 * final)
    if final <= 0 or keep.sum() < 3:
        return None
    slope, intercept = np.polyfit(t[keep], m[keep], 1)
    return slope, intercept, t[keep]


def flow_plot(name, c):
    t, m = c["time"], c["mass"]
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=SIZE)
    top.plot(t, m, label="discharged mass")
    fit = steady_rate(t, m)
    if fit:
        slope, intercept, window = fit
        top.plot(window, slope * window + intercept, "k--", label=f"steady rate {slope:.3g} kg/s (20-80% of the discharge)")
    top.set_ylabel("mass (kg)")
    top.legend(fontsize=7)
    bottom.plot(t, c["rate"], color="tab:orange")
    bottom.set_ylabel("rate (kg/s)")
    bottom.set_xlabel("time (s)")
    return fig, f"Flow probe {name}: discharged mass and rate"


def repose_plot(name, c):
    t, angle = c["time"], c["angle"]
    fig, ax = plt.subplots(figsize=SIZE)
    ax.plot(t, angle, label="angle")
    late = t >= 0.5 * t[-1]
    if late.any() and np.isfinite(angle[late]).any():
        mean = np.nanmean(angle[late])
        ax.axhline(mean, color="k", ls="--", label=f"mean over the second half: {mean:.1f} deg")
    ax.set_xlabel("time (s)")
    ax.set_ylabel("angle of repose (deg)")
    ax.legend(fontsize=7)
    return fig, "Angle of repose" if name == "angle" else f"Angle of repose: {name}"


def fluid_plot(name, c):
    t = c["time"]
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=SIZE)
    for key in c:
        if key.startswith("vz_group_"):
            top.plot(t, c[key], label=f"group {key[len('vz_group_'):]}")
    top.set_ylabel("mean vz (m/s)")
    top.legend(fontsize=7)
    bottom.plot(t, c["outside"], color="tab:red", label="bodies outside the grid")
    bottom.set_ylabel("count")
    bottom.set_xlabel("time (s)")
    return fig, "Fluid probes: settling velocity per group"


def generic_plot(name, c):
    fig, ax = plt.subplots(figsize=SIZE)
    for key, values in c.items():
        if key != "time":
            ax.plot(c["time"], values, label=key)
    ax.set_xlabel("time (s)")
    ax.legend(fontsize=7)
    return fig, name


def kind_of(name, header):
    columns = set(header)
    if {"kinetic", "dissipated"} <= columns:
        return energy_plot
    if name.startswith("driver_") and {"fx", "fy", "fz"} <= columns:
        return driver_plot
    if {"mass", "count", "rate"} <= columns:
        return flow_plot
    if {"angle", "points"} <= columns:
        return repose_plot
    if {"outside", "excess_volume"} <= columns:
        return fluid_plot
    return generic_plot


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: plot.py OUT_DIR PNG_DIR")
    out, png_dir = sys.argv[1], sys.argv[2]
    if not os.path.isdir(out):
        print(f"polydem plot: {out}: no such folder", file=sys.stderr)
        sys.exit(1)
    files = sorted(f for f in os.listdir(out) if f.endswith(".csv"))
    if not files:
        print(f"polydem plot: {out}: no CSV file (was csv_every set?)", file=sys.stderr)
        sys.exit(1)
    os.makedirs(png_dir, exist_ok=True)
    listing = []
    for f in files:
        name = f[:-4]
        header, columns = read_csv(os.path.join(out, f))
        if "time" not in columns or len(columns["time"]) == 0:
            print(f"polydem plot: {f}: no rows, skipped", file=sys.stderr)
            continue
        fig, title = kind_of(name, header)(name, columns)
        fig.suptitle(title)
        fig.tight_layout()
        png = name + ".png"
        fig.savefig(os.path.join(png_dir, png), dpi=DPI, metadata={"Title": title, "Software": "polydem plot"})
        plt.close(fig)
        listing.append(f"{png}\t{title}\n")
        print(f"{os.path.join(png_dir, png)}: {title}")
    with open(os.path.join(png_dir, "plots.txt"), "w") as f:
        f.writelines(listing)


if __name__ == "__main__":
    main()
