"""Work-precision plot: error against wall time per run, log-log, one line per case.

usage: plot.py results.csv out.png [reference.csv]
Also prints, per case, the largest time-step fraction from which every smaller one is below
1% and 0.1% error. A reference CSV (an earlier commit's run) is drawn dashed in the same colours.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    """case -> sorted [(dt_fraction, wall_s, error)], and the commit of the runs."""
    cases, commit = {}, ""
    with open(path) as f:
        for row in csv.DictReader(f):
            commit = row.get("commit", "")
            cases.setdefault(row["case"], []).append(
                (float(row["dt_fraction"]), float(row["wall_s"]), float(row["error"])))
    for runs in cases.values():
        runs.sort()
    return cases, commit


def main(path, png, reference=None):
    cases, commit = read(path)
    fig, ax = plt.subplots(figsize=(7, 5))
    colours = {}
    for name, runs in cases.items():
        line, = ax.loglog([r[1] for r in runs], [max(r[2], 1e-9) for r in runs], "o-", label=f"{name} ({commit})")
        colours[name] = line.get_color()
        for f, w, e in runs[::3]:
            ax.annotate(f"{f:g}", (w, max(e, 1e-9)), fontsize=7, textcoords="offset points", xytext=(3, 3))
        for target in (1e-2, 1e-3):
            ok = [f for f, _, _ in runs if all(e <= target for g, _, e in runs if g <= f)]
            print(f"{name}: error <= {target:g} for dt/critical <= {max(ok) if ok else 'none'}")
    if reference:
        old, old_commit = read(reference)
        for name, runs in old.items():
            ax.loglog([r[1] for r in runs], [max(r[2], 1e-9) for r in runs], "x--", lw=0.8, ms=4,
                      color=colours.get(name, "grey"), label=f"{name} ({old_commit})")
    for target in (1e-2, 1e-3):
        ax.axhline(target, color="grey", lw=0.5, ls="--")
    ax.set_xlabel("wall time per run (s, one core)")
    ax.set_ylabel("relative error")
    ax.set_title("polydem work-precision (labels: dt / critical step)")
    ax.legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(png, dpi=120)


if __name__ == "__main__":
    main(*sys.argv[1:4])
