#!/usr/bin/env python3
"""One function's self instructions by source line, through its inlined calls.

usage: tools/bench/callgrind_lines.py CALLGRIND_OUT BINARY NAME FILE [TOP] [--inner] [--only=src/F:L ...]
  CALLGRIND_OUT  from valgrind --tool=callgrind --dump-instr=yes of a -g build
                 (-DCMAKE_CXX_FLAGS=-g: the Release code, the same counts)
  BINARY         the very build that was profiled
  NAME           a substring of the demangled symbol (every match of `nm -C` counts)
  FILE           each instruction goes to the line of FILE its addr2line -i chain passes through,
                 outermost (the stage that called it: pair_kernel.hpp gives pair_forces_into's
                 steps), or innermost with --inner; an instruction whose chain misses FILE goes
                 under its innermost src/ line, marked "other"
  TOP            rows printed (default 40)
  --only=L       only the instructions whose chain holds src line L (one stage's lines, with --inner)
Each row: instructions, share, the line's most frequent execution count (how often it runs: its
instructions per run are Ir / runs) and the line. callgrind_asm.py then lists one stage's code.
"""
import collections
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent / 'scale'))
from miss_lines import IR, self_costs, short_path, src_chains  # noqa: E402


def address_ranges(binary, name):
    """(start, end) of every symbol whose demangled name holds `name`."""
    ranges = []
    for text in subprocess.run(['nm', '-C', '-S', binary], capture_output=True, text=True).stdout.split('\n'):
        parts = text.split(' ', 3)
        if len(parts) == 4 and parts[2] in 'tTwW' and name in parts[3]:
            start = int(parts[0], 16)
            ranges.append((start, start + int(parts[1], 16)))
    return ranges


def main():
    args = [a for a in sys.argv[1:] if not a.startswith('--')]
    path, binary, name, want = args[:4]
    top = int(args[4]) if len(args) > 4 else 40
    inner = '--inner' in sys.argv
    only = [a[len('--only='):] for a in sys.argv if a.startswith('--only=')]
    ranges = address_ranges(binary, name)
    _, _, by_address = self_costs(path)
    hot = [a for a, v in by_address.items() if v[IR] > 0 and any(lo <= a < hi for lo, hi in ranges)]
    chains = src_chains(binary, hot)
    table, runs = collections.Counter(), collections.defaultdict(collections.Counter)
    for a in hot:
        chain = chains.get(a) or ['(outside src/)']
        if only and not any(line in chain for line in only):
            continue
        hits = [line for line in chain if want in line]
        key = (hits[0] if inner else hits[-1]) if hits else 'other ' + chain[0]
        table[key] += by_address[a][IR]
        runs[key][by_address[a][IR]] += 1
    total = sum(table.values())
    print(f'{total / 1e6:.2f}e6 instructions in {len(ranges)} symbol(s) matching {name!r}')
    for key, ir in table.most_common(top):
        print(f'{ir / 1e6:9.2f}e6 {100 * ir / max(total, 1):5.1f}%  runs {runs[key].most_common(1)[0][0]:>9}  {key}')


if __name__ == '__main__':
    main()
