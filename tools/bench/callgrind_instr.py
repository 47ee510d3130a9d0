#!/usr/bin/env python3
"""Self instructions of one function, instruction by instruction, from a callgrind profile.

Works on the Release binary as built (no -g build needed, which takes a full rebuild: the
project's CMakeLists sets CMAKE_CXX_FLAGS_RELEASE itself, so a -g profile build needs
-DCMAKE_CXX_FLAGS=-g). Run callgrind with --dump-instr=yes, then

    python3 tools/bench/callgrind_instr.py callgrind.out build/polydem 'apply_law<.*BodyPartner' [--blocks]

prints each instruction of the matching function(s) with its count (objdump -d), or with
--blocks the counts that recur (a count shared by many instructions is a path through the
function: per pair, per lane, per contact) with how many instructions carry it.
"""
import collections
import re
import subprocess
import sys


def self_counts(profile, pattern):
    """addr -> Ir of the instructions of the functions whose name matches pattern."""
    counts, names = collections.Counter(), {}
    current, addr, after_call = None, 0, False
    with open(profile) as f:
        for line in f:
            called = re.match(r'cfn=\((\d+)\) (.*)', line)
            if called:  # a name is given once, where it first appears (called or calling)
                names[called.group(1)] = called.group(2).rstrip()
                continue
            fn = re.match(r'fn=\((\d+)\)(?: (.*))?', line)
            if fn:
                if fn.group(2):
                    names[fn.group(1)] = fn.group(2).rstrip()
                current, after_call = names.get(fn.group(1)), False
                continue
            if line.startswith('calls='):
                after_call = True  # the next cost line is the call's inclusive cost
                continue
            cost = re.match(r'(0x[0-9a-f]+|[+-]\d+|\*)\s+\S+\s+(\d+)', line)
            if not cost:
                continue
            a = cost.group(1)
            if a.startswith('0x'):
                addr = int(a, 16)
            elif a[0] in '+-':
                addr += int(a)
            if after_call:
                after_call = False
            elif current and re.search(pattern, current):
                counts[addr] += int(cost.group(2))
    return counts


def main():
    profile, binary, pattern = sys.argv[1:4]
    counts = self_counts(profile, pattern)
    if not counts:
        sys.exit('no instruction counts: was callgrind run with --dump-instr=yes, and does the pattern match?')
    print(f'self Ir {sum(counts.values()):,}')
    if '--blocks' in sys.argv:
        per = collections.Counter(counts.values())
        for count, n in sorted(per.items(), key=lambda cn: -cn[0] * cn[1])[:20]:
            print(f'{n:>6} instructions x {count:>12,} = {n * count:>14,}')
        return
    dis = subprocess.run(['objdump', '-d', '--no-show-raw-insn', '-C', f'--start-address={min(counts)}',
                          f'--stop-address={max(counts) + 16}', binary], capture_output=True, text=True).stdout
    for line in dis.splitlines():
        m = re.match(r'\s*([0-9a-f]+):\s*(.*)', line)
        if m:
            print(f'{counts.get(int(m.group(1), 16), 0):>12,} {m.group(1)} {m.group(2)}')


if __name__ == '__main__':
    main()
