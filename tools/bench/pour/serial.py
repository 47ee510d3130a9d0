#!/usr/bin/env python3
"""What the main thread does outside the parallel regions (issue 19), by function.

    serial.py TWO_SHORT TWO_LONG [ROWS=30]

The arguments are count_efficiency.sh's 2-thread callgrind prefixes (PREFIX-01 is the main
thread). A function's cost outside regions: its calls reached from no `._omp_fn.` function,
shared out by the call graph's inclusive costs (callgrind keeps no call stacks, so a function
called both inside and outside a region is split by its callers' shares). Long less short is
the steps alone. Prints the serial total (as regions.py's), then each function's own work
outside regions and the inclusive work outside regions of the step's serial stages.
"""
import collections
import re
import sys


def parse(path):
    """self[f], edges[(caller, callee)] inclusive, names: the callgrind file's call graph."""
    names, self_cost, edges = {}, collections.Counter(), collections.Counter()
    fn = cfn = None
    pending_call = False

    def name_of(field):
        m = re.match(r'\((\d+)\)(?: (.*))?$', field)
        if not m:
            return field
        if m.group(2) is not None:
            names[m.group(1)] = m.group(2)
        return names.get(m.group(1), m.group(1))

    with open(path) as f:
        for line in f:
            line = line.rstrip('\n')
            if line.startswith('fn='):
                fn = name_of(line[3:])
            elif line.startswith('cfn='):
                cfn = name_of(line[4:])
            elif line.startswith('calls='):
                pending_call = True
            elif line and (line[0].isdigit() or line[0] in '+-*'):
                cost = int(line.split()[-1]) if len(line.split()) > 1 else 0
                if pending_call:
                    edges[(fn, cfn)] += cost
                    pending_call = False
                else:
                    self_cost[fn] += cost
    return self_cost, edges


def in_region(name):
    return '._omp_fn.' in name


def serial_costs(self_cost, edges):
    """(own work outside regions, inclusive work outside regions and not in a region below)."""
    callers, callees = collections.defaultdict(list), collections.defaultdict(list)
    for (p, c), e in edges.items():
        if p != c:
            callers[c].append((p, e))
            callees[p].append((c, e))
    funcs = set(self_cost) | {f for pair in edges for f in pair}
    incl = {f: self_cost[f] + sum(e for _, e in callees[f]) for f in funcs}
    out = {f: 0.0 if in_region(f) else 1.0 for f in funcs}  # share of f's calls made outside regions
    for _ in range(60):  # fixpoint over the call graph (few cycles)
        for f in funcs:
            if in_region(f) or not callers[f]:
                continue
            total = sum(e for _, e in callers[f])
            out[f] = sum(e * out[p] for p, e in callers[f]) / total if total else 1.0
    free = {f: 0.0 if in_region(f) else float(self_cost[f]) for f in funcs}  # incl. less regions below
    for _ in range(60):
        for f in funcs:
            if in_region(f):
                continue
            free[f] = self_cost[f] + sum(e * free[c] / incl[c] for c, e in callees[f] if incl[c])
    own = {f: self_cost[f] * out[f] for f in funcs}
    stage = {f: free[f] * out[f] for f in funcs}
    return own, stage


def main():
    short, long_ = sys.argv[1], sys.argv[2]
    rows = int(sys.argv[3]) if len(sys.argv) > 3 else 30
    own_s, stage_s = serial_costs(*parse(short + '-01'))
    own_l, stage_l = serial_costs(*parse(long_ + '-01'))
    own = {f: own_l.get(f, 0) - own_s.get(f, 0) for f in set(own_l) | set(own_s)}
    stage = {f: stage_l.get(f, 0) - stage_s.get(f, 0) for f in set(stage_l) | set(stage_s)}
    print(f'serial (own work outside regions, summed): {sum(own.values()) / 1e6:.2f}e6')
    print('own work outside regions (millions):')
    for f, v in sorted(own.items(), key=lambda kv: -kv[1])[:rows]:
        print(f'  {v / 1e6:8.2f}  {f[:140]}')
    print('inclusive outside regions, polydem functions (millions):')
    shown = [kv for kv in stage.items() if 'polydem::' in kv[0] and 'lambda' not in kv[0]]
    for f, v in sorted(shown, key=lambda kv: -kv[1])[:rows]:
        print(f'  {v / 1e6:8.2f}  {f[:140]}')


if __name__ == '__main__':
    main()
