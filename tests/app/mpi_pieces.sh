#!/usr/bin/env bash
# A distributed run writes in parallel (issue 20): each rank its bodies' VTK piece, with a
# .pvtu that scene.pvd names, so ParaView opens the run as one data set equal to one
# process's bodies files (tests/app/check_pieces.py); each rank its checkpoint piece, with a
# manifest, resumed on another rank count or in one process on the plain run's bits.
set -euo pipefail
source "$(dirname "$0")/script_lib.bash" "$1"
command -v mpirun > /dev/null || fail "no mpirun: tools/setup.sh installs openmpi-bin"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1  # CI runs as root
expect_timeout=240
mpi() {  # ranks, then polydem's arguments; ranks that wait yield the cores (2 in CI)
  local np=$1; shift
  timeout "$expect_timeout" mpirun --oversubscribe -q --mca mpi_yield_when_idle 1 -np "$np" "$polydem" "$@"
}
# The pour with a frame every 10 ms (5 frames; the first before any step, all bodies on rank 0).
sed -e 's|vtk_every: "20 ms"|vtk_every: "10 ms"|' -e "s|../../shapes|$here/../../shapes|" "$here/mpi_pour.yaml" \
  > "$tmp/pour.yaml"
"$polydem" run "$tmp/pour.yaml" --out "$tmp/plain" --threads 1 > /dev/null 2>&1 || fail "plain pour"
for np in 2 3; do
  mpi "$np" run "$tmp/pour.yaml" --out "$tmp/np$np" --threads 1 > /dev/null 2>&1 || fail "pour at -np $np"
  /usr/bin/python3 "$here/check_pieces.py" "$tmp/plain" "$tmp/np$np" "$np" || fail "-np $np: body pieces"
done
echo "ok: -np 2, 3: bodies_NNNNNN.pvtu and a piece per rank, together the one-process bodies files"
"$polydem" render "$tmp/np2" -o "$tmp/np2.png" > /dev/null 2>&1 || fail "polydem render of the -np 2 pieces"
[ -s "$tmp/np2.png" ] || fail "polydem render wrote no picture of the -np 2 pieces"
echo "ok: polydem render draws the -np 2 run from its .pvtu files"

# Checkpoints in parallel: a manifest and a piece per rank. The -np 2 run's 20 ms checkpoint
# resumed by one process ends on the plain run's state and CSV files (the -np 3 resume:
# mpi_run.sh); so does the -np 2 final checkpoint, joined by one process resuming it at its time.
mid=$tmp/np2/checkpoint_001656.bin
for f in "$mid" "${mid%.bin}_p0.bin" "${mid%.bin}_p1.bin"; do [ -s "$f" ] || fail "no $f"; done
[ "$(head -c 8 "$mid")" = PDCKMA01 ] || fail "$mid is not a manifest"
cp -r "$tmp/np2" "$tmp/one"
rm "$tmp/one"/checkpoint_003313*.bin
"$polydem" run "$tmp/pour.yaml" --out "$tmp/one" --resume "$tmp/one/checkpoint_001656.bin" --threads 1 \
  > /dev/null 2>&1 || fail "one process resuming the -np 2 pieces"
/usr/bin/python3 "$here/same_state.py" "$tmp/plain/checkpoint_003313.bin" "$tmp/one/checkpoint_003313.bin" > /dev/null ||
  fail "-np 2 pieces resumed by one process: another final state"
for f in energy.csv driver_floor.csv driver_left.csv; do
  cmp "$tmp/plain/$f" "$tmp/one/$f" || fail "-np 2 pieces resumed by one process: $f differs"
  cmp "$tmp/plain/$f" "$tmp/np2/$f" || fail "-np 2: $f differs from one process's"
done
"$polydem" run "$tmp/pour.yaml" --out "$tmp/joined" --resume "$tmp/np2/checkpoint_003313.bin" --threads 1 \
  > /dev/null 2>&1 || fail "joining the -np 2 final pieces"
/usr/bin/python3 "$here/same_state.py" "$tmp/plain/checkpoint_003313.bin" "$tmp/joined/checkpoint_003313.bin" \
  > /dev/null || fail "-np 2: another final state"
echo "ok: -np 2 checkpoint pieces resume in one process on the plain run's bits, CSV files included"

# A missing, damaged or foreign piece: one message naming the manifest, the piece and its file,
# exit 1 on every rank (-np 2, no hang) or in one process.
broken() {  # what to do to the copy's 20 ms checkpoint, expected message, ranks (0: one process)
  rm -rf "$tmp/broken" && cp -r "$tmp/np2" "$tmp/broken"
  (cd "$tmp/broken" && eval "$1")
  local run=("$polydem" run "$tmp/pour.yaml" --out "$tmp/broken" --resume "$tmp/broken/checkpoint_001656.bin")
  if [ "$3" = 0 ]; then expect_exit 1 "$2" "${run[@]}"
  else expect_exit 1 "$2" mpirun --oversubscribe -q --mca mpi_yield_when_idle 1 -np "$3" "${run[@]}"
  fi
  [ "$(grep -c "error:" "$tmp/err")" -eq 1 ] || { cat "$tmp/err"; fail "not one message"; }
}
broken "rm checkpoint_001656_p1.bin" "checkpoint_001656.bin: piece 1 of 2 (.*checkpoint_001656_p1.bin) is missing" 2
broken "printf x | dd of=checkpoint_001656_p0.bin bs=1 seek=100 conv=notrunc status=none" \
  "piece 0 of 2 .* is damaged: .*checksum mismatch" 0
broken "cp checkpoint_003313_p0.bin checkpoint_001656_p0.bin" "piece 0 of 2 .* is not the piece the manifest names" 0
echo "ok: a missing, damaged or foreign checkpoint piece: one message naming it, exit 1"
