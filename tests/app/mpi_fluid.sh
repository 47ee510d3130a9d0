#!/usr/bin/env bash
# Drag and fluid forces under mpirun act on each rank's own bodies, their work summed exactly
# over the ranks (no body's state gathered a step): the settling sample (a fluid grid with
# friction, buoyancy and the void fraction) and the pour with quadratic drag (no grid: its
# fluid.csv rows read the velocities gathered to rank 0) end, at -np 1 (2 threads), 2 and 3, on
# the plain run's final state and CSV files (energy with the drag's work, fluid.csv) and fluid
# grid files (the void fraction, rank 0's from the bodies gathered at output) byte for byte; at
# -np 3 no rank keeps the state of the scene's bodies (52 bytes a body at most) and a step
# brings a rank fewer bytes than a gather of every body's state (POLYDEM_MPI_COUNTS).
set -euo pipefail
source "$(dirname "$0")/script_lib.bash" "$1"
source "$here/mpi_lib.bash"
sed -e "s|\.\./\.\./shapes|$here/../../shapes|" -e '/checkpoint_every/d' -e 's|vtk_every: "20 ms"|vtk_every: "50 ms"|' \
  "$here/../../samples/settling/scene.yaml" > "$tmp/settling.yaml"
sed -e "s|\.\./\.\./shapes|$here/../../shapes|" -e '/checkpoint_every/d' "$here/mpi_pour.yaml" > "$tmp/drag.yaml"
sed -i 's|^  - gravity_force:.*|&\n  - quadratic_force: {cx: 0.38, mu: 0.5}|' "$tmp/drag.yaml"

for scene in settling:0.1 drag:0.04; do
  name=${scene%%:*} until=${scene#*:}
  "$polydem" run "$tmp/$name.yaml" --out "$tmp/$name" --until "$until" --threads 1 > /dev/null 2>&1 ||
    fail "plain $name run"
  # the drag's work is in the ledger: not zero, so the exact sum over the ranks is tested
  /usr/bin/python3 -c "import csv, sys; rows = list(csv.DictReader(open(sys.argv[1])))
assert float(rows[-1]['external_work']) < 0, rows[-1]['external_work']" "$tmp/$name/energy.csv" ||
    fail "$name: no work by drag and fluid forces"
  for np in 1 2 3; do
    threads=$((np == 1 ? 2 : 1))
    POLYDEM_MPI_COUNTS=1 mpi "$np" run "$tmp/$name.yaml" --out "$tmp/$name$np" --until "$until" --threads "$threads" \
      > /dev/null 2> "$tmp/$name$np.err" || { cat "$tmp/$name$np.err"; fail "$name at -np $np"; }
    same_outputs "$tmp/$name" "$tmp/$name$np" "$tmp/$name.yaml"
    for f in "$tmp/$name"/fluid_*.vti; do
      [ -e "$f" ] || continue
      cmp "$f" "$tmp/$name$np/$(basename "$f")" || fail "$name: $(basename "$f") differs at -np $np"
    done
  done
  /usr/bin/python3 - "$tmp/${name}3.err" "$name" <<'PY'
import re, sys
text, name = open(sys.argv[1]).read(), sys.argv[2]
held = {int(m[1]): int(m[2]) for m in re.finditer(r"rank (\d) of 3: .*the scene's arrays hold (\d+) bytes a body", text)}
step = {int(m[1]): (int(m[2]), float(m[3]), float(m[4])) for m in re.finditer(
    r"rank (\d) of 3: holds \d+ of (\d+) bodies .*; per step: [\d.]+ point-to-point messages, ([\d.e+]+) bytes; "
    r"[\d.e+]+ collectives, [\d.e+]+ bytes of its own in them, ([\d.e+]+) bytes received", text)}
assert sorted(held) == [0, 1, 2] and sorted(step) == [0, 1, 2], text
for rank, scene_bytes in held.items():
    # the state of the scene's bodies is not kept (224 bytes a body): the constants alone
    assert scene_bytes <= 52, f"{name}: rank {rank}: the scene's arrays hold {scene_bytes} bytes a body"
for rank, (n, sent, received) in step.items():
    # a gather of every body's state each step brought 228 bytes a body to each rank
    assert received < 50 * n, f"{name}: rank {rank} receives {received} bytes a step ({n} bodies)"
print(f"{name}: {held} bytes a body; per step sent / received: " +
      ", ".join(f"rank {r}: {s[1]:.0f} / {s[2]:.0f}" for r, s in sorted(step.items())))
PY
  echo "ok: $name: -np 1, 2, 3 give the plain run's bits, each rank keeping the constants alone"
done
