#!/usr/bin/env python3
"""Per-instruction self counts of one function, beside its disassembly.

usage: tools/bench/callgrind_asm.py CALLGRIND_OUT BINARY NAME [MIN]
  CALLGRIND_OUT  from valgrind --tool=callgrind --dump-instr=yes (the counts of BINARY's object)
  BINARY         the very build that was profiled (a rebuild moves the addresses)
  NAME           a substring of the demangled symbol (the first match of `nm -C`)
  MIN            print only instructions executed at least MIN times (default 0: all)
Prints each instruction's count and the function's total and length (instructions), so a hot
path's instructions per call read directly off the listing (callgrind_annotate stops at lines).
"""
import collections
import subprocess
import sys


def position(token, base):
    """A callgrind position: '*' the same, '+n'/'-n' relative, else absolute (hex with 0x)."""
    if token == '*':
        return base
    if token[0] in '+-':
        return base + int(token)
    return int(token, 16) if token.startswith('0x') else int(token)


def self_counts(path, binary):
    """Instruction address -> self count, for the object named as `binary` (or polydem: a copy)."""
    counts = collections.Counter()
    objects, current = {}, ''
    address = line = 0
    call_cost_next = False  # the line after calls= is a call's inclusive cost, not self
    for raw in open(path):
        s = raw.strip()
        if not s or s[0] == '#':
            continue
        if s[0].isalpha():
            for key in ('ob=', 'cob='):
                if s.startswith(key):
                    ident, _, name = s[len(key):].partition(' ')
                    if name:
                        objects[ident] = name
                    if key == 'ob=':
                        current = objects.get(ident, name)
            call_cost_next = s.startswith('calls=')
            continue
        parts = s.split()
        address, line = position(parts[0], address), position(parts[1], line)
        if call_cost_next:
            call_cost_next = False
            continue
        if current.split('/')[-1] in (binary.split('/')[-1], 'polydem') and len(parts) > 2:
            counts[address] += int(parts[2])
    return counts


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    out, binary, name = sys.argv[1:4]
    least = int(sys.argv[4]) if len(sys.argv) > 4 else 0
    symbols = subprocess.run(['nm', '-S', '-C', binary], capture_output=True, text=True, check=True).stdout
    match = next((l for l in symbols.splitlines() if name in l and len(l.split()) >= 4), None)
    if not match:
        sys.exit(f'no symbol with "{name}" in {binary}')
    start, size = int(match.split()[0], 16), int(match.split()[1], 16)
    listing = subprocess.run(['objdump', '-d', '--no-show-raw-insn', '-C', f'--start-address={start}',
                              f'--stop-address={start + size}', binary], capture_output=True, text=True,
                             check=True).stdout
    counts = self_counts(out, binary)
    total = length = 0
    for l in listing.splitlines():
        head = l.strip().split(':')[0]
        if '\t' not in l or not head or any(ch not in '0123456789abcdef' for ch in head):
            continue
        count = counts.get(int(head, 16), 0)
        total, length = total + count, length + 1
        if count >= least:
            print(f'{count:12d} {l.strip()[:120]}')
    print(f'{total} instructions executed in {match.split(None, 3)[3][:100]} ({length} in its code)')


if __name__ == '__main__':
    main()
