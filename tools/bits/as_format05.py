#!/usr/bin/env python3
"""Writes a checkpoint (format 05 to 08: argv[1]) to stdout as the format-05 file of the same
state: 06 to 08 less their header and checksum, 08 less its body order (the user id per stored
body, first in the payload), 07 and 08 less the energy ledger's open part (each
touching pair's pending energy after its list's slots, the ended contacts' exact sum after both
lists), so run_bits.sh hashes compare across formats (sim/checkpoint.cpp)."""
import struct
import sys

SLOT = 152                # bytes: i, j, slot_fields with format 05's last-step fields
DRIVER = 1 + 9 * 24 + 32  # driver_fields: a flag, nine Vec3, the orientation quaternion
PENDING = 32              # EnergyParts: four doubles
FLUSHED = 8 + 4 * 70 * 8  # ExactEnergy's words as an array: its count, four sums of 70 words


def count(payload, at):
    return struct.unpack_from("<Q", payload, at)[0]


def main():
    data = open(sys.argv[1], "rb").read()
    if data[:8] not in (b"PDCKPT06", b"PDCKPT07", b"PDCKPT08"):
        sys.stdout.buffer.write(data)
        return
    payload = data[40:-8]
    if data[:8] == b"PDCKPT08":
        payload = payload[8 + 4 * count(payload, 0):]
    if data[:8] == b"PDCKPT06":
        sys.stdout.buffer.write(b"PDCKPT05" + payload)
        return
    at = 8 + 8 + 72  # step, dt, ledger
    for size in (24, 32, 24, 24, 24, 24, 24):  # the body arrays, position to torque
        at += 8 + count(payload, at) * size
    at += 8 + count(payload, at) * DRIVER
    parts = [payload[:at]]
    for _ in range(2):  # body pairs, driver pairs: their slots kept, their pending energies left out
        n = count(payload, at)
        end = at + 8 + n * SLOT
        pairs = len({payload[at + 8 + s * SLOT: at + 16 + s * SLOT] for s in range(n)})
        parts.append(payload[at:end])
        at = end + pairs * PENDING
    parts.append(payload[at + FLUSHED:])  # the output progress
    sys.stdout.buffer.write(b"PDCKPT05" + b"".join(parts))


main()
