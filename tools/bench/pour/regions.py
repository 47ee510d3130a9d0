#!/usr/bin/env python3
"""Counted 2-thread efficiency of a window of steps from callgrind profiles (issue 19).

    regions.py ONE_SHORT ONE_LONG TWO_SHORT TWO_LONG

Each argument is a callgrind output prefix (--separate-threads=yes: PREFIX-01 the main
thread, PREFIX-02 the pool's thread). The short run stops just after the start-up, the long one
after STEPS more steps, so long less short is the steps alone. T1 = the 1-thread run's steps;
T2 = thread 0's work outside the regions + for each region (an outlined `._omp_fn.` function,
all its calls) the larger thread's work. Counted efficiency = T1 / (2 T2): what the clock
would give if the threads lost nothing to waiting, memory or the other process on the core.
"""
import collections
import glob
import re
import subprocess
import sys


# Regions whose loops are schedule(dynamic): the rebuild's candidate searches and broad phase
# (body_candidates: spheres' lists; CellList::build_pairs: the region collect_pairs runs in).
DYNAMIC = ('CandidateMemory::find', 'CellList::collect_pairs', 'CellList::merge_pairs', 'body_candidates',
           'CellList::build_pairs')


def inclusive(path):
    """function -> inclusive instructions, and the file's total."""
    out = subprocess.run(['callgrind_annotate', '--inclusive=yes', '--threshold=100', path],
                         capture_output=True, text=True, check=True).stdout
    counts, total = {}, 0
    for line in out.splitlines():
        m = re.match(r'\s*([\d,]+) \([^)]*\)\s+(\S.*)$', line)
        if not m:
            continue
        n = int(m.group(1).replace(',', ''))
        name = re.sub(r' \[[^\]]*\]$', '', m.group(2))
        if 'PROGRAM TOTALS' in name:
            total = n
            continue
        name = name.split(':', 1)[1] if ':' in name else name
        counts[name] = counts.get(name, 0) + n
    return counts, total


def threads(prefix):
    """[(counts, total)] a thread, the main thread first."""
    return [inclusive(f) for f in sorted(glob.glob(prefix + '-*'))]


def window(short, long_):
    """Each thread's counts of the steps alone: long less short."""
    result = []
    for (c0, t0), (c1, t1) in zip(threads(short), threads(long_)):
        result.append(({k: c1.get(k, 0) - c0.get(k, 0) for k in set(c0) | set(c1)}, t1 - t0))
    return result


def regions(counts):
    """Outlined region functions; a region nested in none other (inclusive counts nest)."""
    return {k: v for k, v in counts.items() if '._omp_fn.' in k and v > 0}


def main():
    one_s, one_l, two_s, two_l = sys.argv[1:5]
    (one, t1_total), = window(one_s, one_l)[:1]
    two = window(two_s, two_l)
    (c0, total0), (c1, total1) = two[0], two[1]
    r0, r1 = regions(c0), regions(c1)
    names = sorted(set(r0) | set(r1), key=lambda k: -max(r0.get(k, 0), r1.get(k, 0)))
    serial0 = total0 - sum(r0.values())
    outside1 = total1 - sum(r1.values())
    maxima = sum(max(r0.get(k, 0), r1.get(k, 0)) for k in names)
    t2 = serial0 + maxima
    print(f'1 thread, the steps: {t1_total / 1e6:.2f}e6 (start-up run {threads(one_s)[0][1] / 1e6:.2f}e6)')
    print(f'2 threads, the steps: thread 0 {total0 / 1e6:.2f}e6, thread 1 {total1 / 1e6:.2f}e6, '
          f'together {(total0 + total1) / t1_total:.4f} of 1 thread')
    print(f'serial (thread 0 outside regions) {serial0 / 1e6:.2f}e6; thread 1 outside regions {outside1 / 1e6:.2f}e6')
    print(f'regions: {len(names)}, summed larger thread {maxima / 1e6:.2f}e6, summed mean {(sum(r0.values()) + sum(r1.values())) / 2e6:.2f}e6')
    print(f'T2 = serial + maxima = {t2 / 1e6:.2f}e6; counted efficiency T1 / (2 T2) = {t1_total / (2 * t2):.3f}')
    # valgrind runs one thread at a time, so a dynamic loop's split is its own (one thread may take
    # every chunk): with each region at its threads' mean, the bound for perfectly shared loops.
    t2_mean = serial0 + (sum(r0.values()) + sum(r1.values())) / 2
    print(f'with each region at its mean: T2 = {t2_mean / 1e6:.2f}e6, efficiency {t1_total / (2 * t2_mean):.3f}')
    # The rebuild's dynamic loops split as valgrind happens to run the threads (0.83-0.86 above
    # from one binary); the other regions' splits are fixed by their cuts: the same every run.
    t2_fixed = serial0 + sum((r0.get(k, 0) + r1.get(k, 0)) / 2 if any(d in k for d in DYNAMIC)
                             else max(r0.get(k, 0), r1.get(k, 0)) for k in names)
    print(f'with the dynamic loops at their mean: T2 = {t2_fixed / 1e6:.2f}e6, efficiency {t1_total / (2 * t2_fixed):.3f}')
    print('largest regions (millions, thread 0 / thread 1, loss = max - mean):')
    for k in names[:25]:
        a, b = r0.get(k, 0), r1.get(k, 0)
        print(f'  {a / 1e6:9.2f} {b / 1e6:9.2f}  loss {(max(a, b) - (a + b) / 2) / 1e6:7.2f}  {k[:130]}')


if __name__ == '__main__':
    main()
