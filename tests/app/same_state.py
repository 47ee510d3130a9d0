"""Two format-08 checkpoints hold the same state: the same header (but the payload's size) and
the same payload up to the output progress, its last part, whose file names may differ (a
distributed run's frames name bodies_NNNNNN.pvtu where one process names .vtu). The progress's
size follows from the scene.pvd beside each checkpoint: per frame, its time and file names.

usage: same_state.py CHECKPOINT_A CHECKPOINT_B   (exit 1 and a message when they differ)
"""
import os
import struct
import sys
import xml.etree.ElementTree as ET

HEADER = 8 + 4 * 8  # magic, then fingerprint, bodies, drivers, payload bytes (uint64)


def progress_bytes(checkpoint):
    """Bytes of the output progress: frame counter, frame count, per frame its time, file count
    and names (uint64 length + characters), from the scene.pvd beside the checkpoint."""
    pvd = os.path.join(os.path.dirname(checkpoint), "scene.pvd")
    frames = {}
    if os.path.exists(pvd):
        for d in ET.parse(pvd).getroot().iter("DataSet"):
            frames.setdefault(d.get("timestep"), []).append(d.get("file"))
    return 16 + sum(16 + sum(8 + len(f.encode()) for f in files) for files in frames.values()), len(frames)


def state(checkpoint):
    data = open(checkpoint, "rb").read()
    if data[:8] != b"PDCKPT08":
        sys.exit(f"{checkpoint}: not a format-08 checkpoint ({data[:8]!r})")
    progress, frames = progress_bytes(checkpoint)
    end = len(data) - 8 - progress  # before the progress and the checksum
    frame_counter, frame_count = struct.unpack_from("<qQ", data, end)
    if frame_count != frames:
        sys.exit(f"{checkpoint}: {frame_count} frames where its scene.pvd has {frames}")
    return data[:8 + 3 * 8], data[HEADER:end], frame_counter


a, b = state(sys.argv[1]), state(sys.argv[2])
for what, x, y in zip(("header", "state", "frame counter"), a, b):
    if x != y:
        sys.exit(f"{sys.argv[2]}: its {what} differs from {sys.argv[1]}'s")
print(f"same state: {len(a[1])} bytes of payload before the output progress")
