#!/usr/bin/env python3
"""Where a step's last-level misses come from: self costs by function and by source line of two
callgrind profiles of the same scene, S and 2S steps (2S less S: the steps alone, without the
set-up, the resume and its list build), per body-step.

usage: tools/bench/scale/miss_lines.py SHORT.out LONG.out BODY_STEPS [BINARY [TOP]]
  SHORT.out, LONG.out  callgrind --cache-sim=yes --dump-instr=yes profiles (run_scale_sim.sh's
                       cache options) of a -g build (-DCMAKE_CXX_FLAGS=-g: the same code, the
                       same counts); without -g the functions alone tell
  BODY_STEPS           bodies times the S steps between the two
  BINARY               the profiled build: each instruction's line is then its innermost line in
                       src/ (addr2line -i), not an Eigen or intrinsics header inlined there, with
                       the two src/ lines it was inlined into
  TOP                  rows printed of each table (default 40)
Prints per body-step the instructions, L1 and last-level misses (reads and writes apart) of the
functions and of the source lines, largest last-level first: which array a line reads is then
one look at the line (README, "The bytes a cube-step streams": the settled piles' table).
"""
import collections
import re
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # tools/bench
from callgrind_asm import position  # noqa: E402

# callgrind's events with --cache-sim=yes: Ir Dr Dw I1mr D1mr D1mw ILmr DLmr DLmw
IR, I1MR, D1MR, D1MW, ILMR, DLMR, DLMW = 0, 3, 4, 5, 6, 7, 8
EVENTS = 9


def self_costs(path):
    """(function -> events, (file, line) -> events): self costs, a call's inclusive cost left out."""
    by_function = collections.defaultdict(lambda: [0] * EVENTS)
    by_line = collections.defaultdict(lambda: [0] * EVENTS)
    by_address = collections.defaultdict(lambda: [0] * EVENTS)
    names = {'fn': {}, 'fl': {}}  # name compression: "(id) name" once, "(id)" after
    file = inlined = function = ''
    columns, last = 1, [0, 0]
    after_call = False
    for text in open(path):
        if text.startswith('positions:'):
            columns = len(text.split()) - 1  # "instr line" with --dump-instr=yes, else "line"
            continue
        if text[:1].isdigit() or text[:1] in '+-*':
            parts = text.split()
            last = [position(parts[c], last[c]) for c in range(columns)] + last[columns:]
            if after_call:  # the cost line after calls= is the callee's inclusive cost
                after_call = False
                continue
            costs = [int(x) for x in parts[columns:]]
            line = last[columns - 1]
            targets = [by_function[function], by_line[(inlined or file, line)]]
            if columns == 2:
                targets.append(by_address[last[0]])
            for target in targets:
                for e, x in enumerate(costs):
                    target[e] += x
            continue
        match = re.match(r'(\w+)=(.*)', text.rstrip('\n'))
        if not match:
            continue
        key, value = match.groups()
        if key == 'calls':
            after_call = True
            continue
        if key not in ('fl', 'fi', 'fe', 'fn', 'cfn', 'cfl', 'cfi'):
            continue
        table = names['fn' if key in ('fn', 'cfn') else 'fl']
        compressed = re.match(r'\((\d+)\)(?: (.*))?', value)
        if compressed:
            if compressed.group(2) is not None:
                table[compressed.group(1)] = compressed.group(2)
            value = table[compressed.group(1)]
        if key == 'fl':
            file, inlined = value, ''
        elif key in ('fi', 'fe'):
            inlined = '' if value == file else value
        elif key == 'fn':
            function = value
    return by_function, by_line, by_address


def src_chains(binary, addresses):
    """Address -> its src/ lines from innermost to outermost (addr2line -i)."""
    out = []
    for i in range(0, len(addresses), 5000):
        out += subprocess.run(['addr2line', '-i', '-a', '-e', binary] + [hex(a) for a in addresses[i:i + 5000]],
                              capture_output=True, text=True, check=True).stdout.split('\n')
    chains, address = {}, None
    for text in out:
        if text.startswith('0x'):
            address = int(text, 16)
            chains[address] = []
        elif address is not None and text:
            where = short_path(re.sub(r' \(discriminator \d+\)', '', text))
            if where.startswith('src/'):
                chains[address].append(where)
    return chains


def project_lines(by_address, binary, per):
    """(innermost src/ line, the two it was inlined into) -> events, for the instructions with
    a last-level miss in 500 body-steps at least (addr2line's inline chains)."""
    hot = [a for a, v in by_address.items() if abs(last_level(v)) * 500 >= per]
    chains = src_chains(binary, hot)
    by_line = collections.defaultdict(lambda: [0] * EVENTS)
    for a in hot:
        chain = chains.get(a) or ['(outside src/)']
        key = chain[0] + (f'  [{" <- ".join(chain[1:3])}]' if len(chain) > 1 else '')
        for e, x in enumerate(by_address[a]):
            by_line[key][e] += x
    return by_line


def difference(short, long):
    return {k: [long.get(k, [0] * EVENTS)[e] - short.get(k, [0] * EVENTS)[e] for e in range(EVENTS)]
            for k in set(short) | set(long)}


def short_path(path):
    """A source path from the repository's src/ or include/ on."""
    return re.sub(r'^.*?/(src|include)/', r'\1/', path)


def last_level(v):
    return v[ILMR] + v[DLMR] + v[DLMW]


def show(table, title, per, top):
    total = [sum(v[e] for v in table.values()) / per for e in range(EVENTS)]
    print(f'== {title}, per body-step: Ir {total[IR]:.1f}, L1 misses {total[I1MR] + total[D1MR] + total[D1MW]:.2f}, '
          f'LL misses {last_level(total):.3f} ({total[DLMR]:.3f} reads, {total[DLMW]:.3f} writes)')
    print('   LL    reads  writes        Ir     L1  where')
    for key, v in sorted(table.items(), key=lambda kv: -last_level(kv[1]))[:top]:
        if abs(last_level(v)) / per < 0.005:
            break
        where = key if isinstance(key, str) else short_path(key[0]) + f':{key[1]}'
        print(f'{last_level(v) / per:7.3f} {v[DLMR] / per:7.3f} {v[DLMW] / per:7.3f} {v[IR] / per:9.1f} '
              f'{(v[D1MR] + v[D1MW]) / per:6.2f}  {where[:160]}')


def main():
    if len(sys.argv) not in (4, 5, 6):
        sys.exit(__doc__)
    short, long = self_costs(sys.argv[1]), self_costs(sys.argv[2])
    per = float(sys.argv[3])
    binary = sys.argv[4] if len(sys.argv) > 4 else None
    top = int(sys.argv[5]) if len(sys.argv) > 5 else 40
    show(difference(short[0], long[0]), 'functions', per, top)
    if binary:
        show(project_lines(difference(short[2], long[2]), binary, per), 'innermost src/ lines', per, top)
    else:
        show(difference(short[1], long[1]), 'source lines', per, top)


if __name__ == '__main__':
    main()
