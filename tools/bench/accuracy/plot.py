"""Work-precision plot: error against wall time per run, log-log, one line per case.

usage: plot.py results.csv out.png [reference.csv]
Also prints, per case, the largest time-step fraction from which every smaller one is below
1% and 0.1% error, the observed order between neighbouring steps, the least-squares slope over
errors 1e-4 to 1e-2 (the reference's too), and against the reference
the wall time from which every smaller step stays within 1e-3. A reference CSV (an earlier commit's run) is drawn dashed in the same colours.
"""
import csv
import math
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


def at_error(runs, target):
    """(dt fraction, wall time per run) from which every smaller step stays within target: from the
    smallest step up to the first run above it (log-log between that run and the one below), so a
    lucky sign change of the error at one step (the old cube corner's 2e-6 at 0.03) does not count;
    the largest step if none is above, None if the smallest is."""
    runs = sorted(runs)  # smallest step first
    if not runs or runs[0][2] > target:
        return None
    for (f0, w0, e0), (f1, w1, e1) in zip(runs, runs[1:]):
        if e1 > target:
            if e0 <= 0:
                return f0, w0
            t = math.log(target / e0) / math.log(e1 / e0)
            return f0 * (f1 / f0) ** t, w0 * (w1 / w0) ** t
    return runs[-1][:2]


def orders(runs):
    """Observed order between neighbouring steps, largest first, down to an error of 1e-5."""
    runs = sorted(runs, reverse=True)
    return [(f0, math.log(e0 / e1) / math.log(f0 / f1)) for (f0, _, e0), (f1, _, e1) in zip(runs, runs[1:])
            if e0 > 0 and e1 > 1e-5]


def slope(runs, low=1e-4, high=1e-2):
    """Least-squares slope of log error on log dt over the runs whose error is within [low, high]
    (issue 16's "slope 2 down to 1e-4"), with the step fractions it spans; None under two runs."""
    window = [(math.log(f), math.log(e)) for f, _, e in runs if low <= e <= high]
    if len(window) < 2:
        return None
    mx = sum(x for x, _ in window) / len(window)
    my = sum(y for _, y in window) / len(window)
    fit = sum((x - mx) * (y - my) for x, y in window) / sum((x - mx) ** 2 for x, _ in window)
    return fit, math.exp(min(window)[0]), math.exp(max(window)[0]), len(window)


def main(path, png, reference=None):
    cases, commit = read(path)
    fig, ax = plt.subplots(figsize=(7, 5))
    colours = {}
    for k, (name, runs) in enumerate(cases.items()):  # tab20: no colour shared by two of up to 20 cases
        line, = ax.loglog([r[1] for r in runs], [max(r[2], 1e-9) for r in runs], "o-", color=plt.cm.tab20(k % 20),
                          label=f"{name} ({commit})")
        colours[name] = line.get_color()
        for f, w, e in runs[::3]:
            ax.annotate(f"{f:g}", (w, max(e, 1e-9)), fontsize=7, textcoords="offset points", xytext=(3, 3))
        for target in (1e-2, 1e-3):
            ok = [f for f, _, _ in runs if all(e <= target for g, _, e in runs if g <= f)]
            print(f"{name}: error <= {target:g} for dt/critical <= {max(ok) if ok else 'none'}")
        print(f"{name}: order " + " ".join(f"{f:g}:{o:.1f}" for f, o in orders(runs)))
        fit = slope(runs)
        if fit:
            print(f"{name}: slope {fit[0]:.2f} over errors 1e-4 to 1e-2 (dt/critical {fit[1]:g} to {fit[2]:g}, {fit[3]} runs)")
    if reference:
        old, old_commit = read(reference)
        for name, runs in old.items():
            fit = slope(runs)
            if fit:
                print(f"{name} at {old_commit}: slope {fit[0]:.2f} over errors 1e-4 to 1e-2 (dt/critical {fit[1]:g} to {fit[2]:g})")
        for name in old.keys() & cases.keys():
            new, before = at_error(cases[name], 1e-3), at_error(old[name], 1e-3)
            if new and before:
                print(f"{name}: at 1e-3 error, dt/critical {before[0]:.3g} at {old_commit} -> {new[0]:.3g} "
                      f"({new[0] / before[0]:.1f}x fewer steps), wall time {before[1]:.3g} s -> {new[1]:.3g} s "
                      f"({before[1] / new[1]:.1f}x less)")
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
