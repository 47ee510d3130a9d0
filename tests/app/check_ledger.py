"""The energy ledger of a run's energy.csv (columns as README documents them) closes:
gravity_work + driver_work + external_work - (kinetic + rotational + elastic - their start)
- dissipated stays within TOLERANCE of the largest term over the run, on every row.

usage: check_ledger.py OUT_DIR TOLERANCE [TERM]   (exit 1 naming the worst row if it does not;
TERM, a column that must end at half the largest term at least: the scene did what it is for)
"""
import csv
import sys

STORED = ("kinetic", "rotational", "elastic")
WORK = ("gravity_work", "driver_work", "external_work")


def residuals(rows):
    """(time, residual J) per row, against the first row's stored energy."""
    start = sum(float(rows[0][k]) for k in STORED)
    for r in rows:
        stored = sum(float(r[k]) for k in STORED) - start
        yield float(r["time"]), sum(float(r[k]) for k in WORK) - stored - float(r["dissipated"])


def main(out, tolerance, term=None):
    with open(f"{out}/energy.csv") as f:
        rows = list(csv.DictReader(f))
    largest = max(abs(float(r[k])) for r in rows for k in STORED + WORK + ("dissipated",))
    time, worst = max(residuals(rows), key=lambda tr: abs(tr[1]))
    last = rows[-1]
    shares = ", ".join(f"{k} {float(last[k]) / largest:.3f}" for k in ("dissipated",) + WORK)
    print(f"{out}: {len(rows)} rows, largest term {largest:.4g} J; worst residual {worst:.3g} J "
          f"({abs(worst) / largest:.2e} of it) at t = {time:g} s; at the end, shares: {shares}")
    if not abs(worst) <= float(tolerance) * largest:
        print(f"FAIL: the ledger does not close within {tolerance} of the largest term")
        sys.exit(1)
    if term and not float(last[term]) >= 0.5 * largest:
        print(f"FAIL: {term} ends at {float(last[term]):.4g} J, under half the largest term")
        sys.exit(1)


if __name__ == "__main__":
    main(*sys.argv[1:4])
