#!/usr/bin/env python3
"""What N ranks do beyond one process, counted (issue 20), from callgrind files of whole runs.

    rank_counts.py ONE_SHORT ONE_LONG RANKS_SHORT RANKS_LONG [TOP]

ONE_* are one process's callgrind files, RANKS_* the prefixes of the ranks' files (PREFIX.0,
PREFIX.1, ...). Only the polydem binary's own functions count (self instructions; MPI's and
libc's left out: OpenMPI's polling moves with the load); ALL=1 counts every object's (MPI's
waits included: a rank polling for the other shows there). Long less short is the steps alone.
Prints each rank, their sum, one process, the sum's excess over it, efficiency = one process /
(N x slower rank), then the TOP functions (default 25) whose ranks' sum exceeds one process's most.
"""
import glob
import re
import subprocess
import os
import sys

EVERY_OBJECT = os.environ.get('ALL') == '1'


def own_counts(path):
    """function -> self instructions of the functions in the polydem binary."""
    out = subprocess.run(['callgrind_annotate', '--threshold=100', path],
                         capture_output=True, text=True, check=True).stdout
    counts = {}
    for line in out.splitlines():
        m = re.match(r'\s*([\d,]+) \([^)]*\)\s+(\S.*) \[([^\]]*)\]$', line)
        if not m or not (EVERY_OBJECT or m.group(3).endswith('polydem')):
            continue
        name = m.group(2).split(':', 1)[1] if ':' in m.group(2) else m.group(2)
        counts[name] = counts.get(name, 0) + int(m.group(1).replace(',', ''))
    return counts


def window(short, long_):
    """Each function's counts of the steps alone: long less short."""
    a, b = own_counts(short), own_counts(long_)
    return {k: b.get(k, 0) - a.get(k, 0) for k in set(a) | set(b)}


def rank_files(prefix):
    return sorted(glob.glob(prefix + '.*'), key=lambda p: int(p.rsplit('.', 1)[1]))


def main():
    one_short, one_long, ranks_short, ranks_long = sys.argv[1:5]
    top = int(sys.argv[5]) if len(sys.argv) > 5 else 25
    one = window(one_short, one_long)
    ranks = [window(s, l) for s, l in zip(rank_files(ranks_short), rank_files(ranks_long))]
    totals = [sum(r.values()) for r in ranks]
    one_total = sum(one.values())
    for k, t in enumerate(totals):
        print(f'rank {k}: {t / 1e6:.2f}e6')
    summed = sum(totals)
    print(f'ranks summed: {summed / 1e6:.2f}e6, one process: {one_total / 1e6:.2f}e6, '
          f'excess: {(summed - one_total) / 1e6:+.2f}e6 ({100 * (summed - one_total) / one_total:+.2f}%)')
    print(f'efficiency: {one_total / (len(ranks) * max(totals)):.4f}')
    names = set(one).union(*ranks)
    excess = {n: sum(r.get(n, 0) for r in ranks) - one.get(n, 0) for n in names}
    print(f'\n{"ranks - one":>12} {"one":>12}  function (self instructions, the steps alone)')
    for n in sorted(names, key=lambda n: -abs(excess[n]))[:top]:
        print(f'{excess[n]:12,d} {one.get(n, 0):12,d}  {n[:140]}')


if __name__ == '__main__':
    main()
