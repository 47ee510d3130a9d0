#!/usr/bin/env python3
"""The main thread's timeline of waits, per step and per rebuild, from callgrind parts (issue 19).

    waits.py PREFIX [SKIP=10]

PREFIX is count_waits.sh's callgrind output (--separate-threads=yes, --toggle-collect on the
step, a part dumped before and after each GOMP_parallel, before each step and after each
rebuild): PREFIX.N-01 are the main thread's parts in order. A part that ends after
GOMP_parallel is a region (its opener: the function that called GOMP_parallel); every other
part is serial work of thread 0 (between two regions, or a region and the step's ends), joined
into stretches: a stretch is what the other thread waits through asleep once it outlasts
libgomp's spin (GOMP_SPINCOUNT=1000 pauses, ~15-50 us here: ~3e4-1e5 instructions), and then
each region that follows pays a futex wake-up. Barriers met: thread 0's calls to GOMP_barrier
(a static loop's or a single's end, an explicit barrier), GOMP_loop_end (a dynamic loop's end),
GOMP_single_start, GOMP_critical*_start (a lock, met even alone), inside its regions only. The first SKIP steps (start-up) are
left out. Prints the steps with and without a rebuild, each rebuild, and the stretches by size.
"""
import collections
import glob
import re
import sys

BARRIERS = {'GOMP_barrier': 'barrier', 'GOMP_loop_end': 'loop_end', 'GOMP_single_start': 'single',
            'GOMP_critical_start': 'critical', 'GOMP_critical_name_start': 'critical'}
BINS = (1e3, 1e4, 3e4, 1e5, 1e6, float('inf'))  # stretch sizes, instructions


def read_part(path, names):
    """(trigger, instructions, opener of GOMP_parallel or None, barrier calls by kind, each
    function's own instructions); `names`: the run's compressed names (id -> name), defined once
    in the first part that uses them."""
    fn, trigger, total, opener = None, '', 0, None
    calls, callee, own, call_line = collections.Counter(), None, collections.Counter(), False
    with open(path) as f:
        for line in f:
            if line[:1].isdigit() or line[:1] in '+-*':  # a cost line: a call's inclusive cost or fn's own
                if not call_line:
                    fields = line.split()
                    own[fn] += int(fields[1]) if len(fields) > 1 else 0
                call_line = False
            elif line.startswith('desc: Trigger:'):
                trigger = line.split(':', 2)[2].strip()
            elif line.startswith('totals:'):
                total = int(line.split()[1])
            elif line.startswith(('fn=', 'cfn=')):
                m = re.match(r'c?fn=\((\d+)\)(?: (.*))?$', line.rstrip('\n'))
                name = names.setdefault(m.group(1), m.group(2)) if m else line.split('=', 1)[1].strip()
                if line.startswith('fn='):
                    fn = name
                else:
                    callee = name
                    if name == 'GOMP_parallel' and opener is None:
                        opener = fn
            elif line.startswith('calls='):
                call_line = True
                if callee in BARRIERS:
                    calls[BARRIERS[callee]] += int(line.split()[0].split('=')[1])
    return trigger, total, opener, calls, own


def short(name):
    """A region's opener without its arguments, return type and namespace."""
    name, depth = (name or '?').replace('polydem::', '').replace('(anonymous namespace)::', ''), 0
    for k, c in enumerate(name):
        depth += (c == '<') - (c == '>')
        if c == ' ' and depth == 0:
            name, depth = name[k + 1:], 0
            return short(name) if '(' in name else name
        if c == '(' and depth == 0:
            return name[:k]
    return name


class Step:
    """A step's parts in order: ('region', opener, instructions, barrier calls) or ('serial', n)."""

    def __init__(self, parts):
        self.parts = parts
        self.regions = [(p[1], p[2]) for p in parts if p[0] == 'region']
        self.barriers = collections.Counter()
        for p in parts:
            if p[0] == 'region':
                self.barriers.update(p[3])
        self.stretches, run = [], 0
        for p in parts:
            if p[0] == 'serial':
                run += p[1]
            elif p[0] == 'region':
                self.stretches.append(run) if run else None
                run = 0
        if run:
            self.stretches.append(run)
        self.rebuilds = [self.rebuild()] if any(p[0] == 'rebuilt' for p in parts) else []

    def rebuild(self):
        """The rebuild's regions and serial work: from the end of the step's first region (the
        serial rebuild decision included, a few 1e3 instructions) to the rebuild's return."""
        r, first = collections.Counter(), next(k for k, p in enumerate(self.parts) if p[0] == 'region')
        for p in self.parts[first + 1:]:
            if p[0] == 'rebuilt':
                break
            if p[0] == 'serial':
                r['serial'] += p[1]
            else:
                r['regions'] += 1
                r['barriers'] += sum(p[3].values())
                r['region_work'] += p[2]
        return r


def timeline(prefix):
    parts = sorted(glob.glob(prefix + '.*-01'), key=lambda p: int(re.search(r'\.(\d+)-01$', p).group(1)))
    steps, step, names = [], None, {}
    for path in parts:
        trigger, total, opener, calls, own = read_part(path, names)
        if step is None:
            if 'Simulation::step' in trigger:
                step = []
            continue
        if trigger.startswith('--dump-after=GOMP_parallel') and (opener or total):  # else outside the step
            step.append(('region', short(opener), total, calls))
            continue
        step.append(('serial', total, own))
        if trigger.startswith('--dump-after=polydem::ContactEngine::rebuild') and trigger.endswith('bool)'):
            step.append(('rebuilt',))
        elif 'Simulation::step' in trigger:
            steps.append(Step(step))
            step = []
    return steps


def mean(xs):
    return sum(xs) / len(xs) if xs else 0.0


def report(label, steps):
    if not steps:
        return
    n = len(steps)
    stretches = [s for st in steps for s in st.stretches]
    barriers = collections.Counter()
    for st in steps:
        barriers.update(st.barriers)
    kinds = ', '.join(f'{k} {v / n:.2f}' for k, v in sorted(barriers.items()))
    print(f'{label}: {n} steps; a step: regions {mean([len(s.regions) for s in steps]):.2f}, barriers '
          f'{sum(barriers.values()) / n:.2f} ({kinds}), serial stretches {len(stretches) / n:.2f} holding '
          f'{sum(stretches) / n / 1e3:.1f}e3 instructions, the longest {max(stretches, default=0) / 1e3:.1f}e3, '
          f'over 3e4: {sum(s > 3e4 for s in stretches) / n:.2f}')


def histogram(steps):
    stretches = [s for st in steps for s in st.stretches]
    lo = 0
    print('serial stretches of thread 0 by size (instructions): count, summed instructions')
    for hi in BINS:
        inside = [s for s in stretches if lo <= s < hi]
        print(f'  [{lo:.0e}, {hi:.0e}): {len(inside)}, {sum(inside) / 1e6:.3f}e6')
        lo = hi


def main():
    prefix, skip = sys.argv[1], int(sys.argv[2]) if len(sys.argv) > 2 else 10
    steps = timeline(prefix)[skip:]
    rebuilding = [s for s in steps if s.rebuilds]
    print(f'{len(steps)} steps counted (the first {skip} left out), {len(rebuilding)} with a rebuild')
    report('all steps', steps)
    report('steps without a rebuild', [s for s in steps if not s.rebuilds])
    report('steps with a rebuild', rebuilding)
    builds = [r for s in rebuilding for r in s.rebuilds]
    if builds:
        print(f'a rebuild: regions {mean([r["regions"] for r in builds]):.2f}, barriers in them '
              f'{mean([r["barriers"] for r in builds]):.2f}, serial {mean([r["serial"] for r in builds]) / 1e3:.1f}e3 '
              f'instructions, its regions on thread 0 {mean([r["region_work"] for r in builds]) / 1e3:.1f}e3')
    histogram(steps)
    if rebuilding:
        median = sorted(rebuilding, key=lambda s: sum(s.stretches))[len(rebuilding) // 2]
        print('the median rebuild step in order: serial stretches and regions (thread 0 instructions)')
        run, own = 0, collections.Counter()
        for p in median.parts + [('region', '(the step ends)', 0, {})]:
            if p[0] == 'serial':
                run += p[1]
                own.update(p[2])
            elif p[0] == 'region':
                if run:
                    top = ', '.join(f'{short(k)} {v / 1e3:.1f}' for k, v in own.most_common(4))
                    print(f'  serial {run / 1e3:8.1f}e3  (own e3: {top})' if run >= 1e4 else f'  serial {run / 1e3:8.1f}e3')
                print(f'  region {p[2] / 1e3:8.1f}e3  {p[1]}')
                run, own = 0, collections.Counter()
    longest = max((p for st in steps for p in st.parts if p[0] == 'serial'), key=lambda p: p[1], default=None)
    if longest and longest[1] >= 1e4:
        top = ', '.join(f'{short(k)} {v / 1e3:.1f}' for k, v in longest[2].most_common(5))
        print(f'the longest serial part {longest[1] / 1e3:.1f}e3 (own e3: {top})')
    openers = collections.Counter(), collections.Counter()
    for st in steps:
        for name, work in st.regions:
            openers[0][name] += 1
            openers[1][name] += work
    print('regions by opener: a step, thread 0 instructions a call')
    for name, count in openers[0].most_common():
        print(f'  {count / len(steps):6.3f}  {openers[1][name] / count / 1e3:9.1f}e3  {name}')


if __name__ == '__main__':
    main()
