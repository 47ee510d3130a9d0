#!/usr/bin/env bash
# A distributed run writes in parallel (issue 20): each rank its bodies' VTK piece, with a
# .pvtu that scene.pvd names, so ParaView opens the run as one data set equal to one
# process's bodies files (tests/app/check_pieces.py); each rank its checkpoint piece, with a
# manifest, resumed on another rank count or in one process on the plain run's bits, also after
# SIGTERM on mpirun.
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

# SIGTERM on mpirun (it passes it to the ranks, as a batch scheduler's stop or Ctrl-C does):
# every rank stops at the same step (the signal is ORed over the ranks each step) and one
# checkpoint is written, a manifest and its pieces; resumed with -np 3 it ends on the plain
# run's state and energy.csv. The signal goes once the 10 ms frame is written (the ranks see it
# some 0.3 s later, at 40-80 ms here), well before the 200 ms the runs are compared at.
last_checkpoint() { ls "$1"/checkpoint_*.bin | grep -v '_p[0-9]*\.bin$' | sort | tail -1; }
"$polydem" run "$tmp/pour.yaml" --out "$tmp/plain200" --until 0.2 --threads 1 > /dev/null 2>&1 || fail "plain to 0.2 s"
timeout "$expect_timeout" mpirun --oversubscribe -q --mca mpi_yield_when_idle 1 -np 2 "$polydem" run \
  "$tmp/pour.yaml" --out "$tmp/stopped" --until 5 --threads 1 > /dev/null 2> "$tmp/stopped.err" &
runner=$!
until [ -e "$tmp/stopped/bodies_000001.pvtu" ]; do
  kill -0 "$runner" 2> /dev/null || { cat "$tmp/stopped.err"; fail "the -np 2 run ended before the signal"; }
  sleep 0.01
done
kill -TERM "$runner"  # timeout passes it to mpirun
wait "$runner" || true
stopped=$(sed -n 's/^interrupted at t = .* --resume \(.*\)$/\1/p' "$tmp/stopped.err")
[ "$(grep -c "^interrupted at t" "$tmp/stopped.err")" -eq 1 ] && [ -n "$stopped" ] ||
  { cat "$tmp/stopped.err"; fail "SIGTERM at -np 2: not one interruption message"; }
[ "$(head -c 8 "$stopped")" = PDCKMA01 ] && [ -s "${stopped%.bin}_p0.bin" ] && [ -s "${stopped%.bin}_p1.bin" ] ||
  fail "SIGTERM at -np 2: no manifest and pieces at $stopped"
end=$(last_checkpoint "$tmp/plain200")
step=$(basename "$stopped" .bin); step=$((10#${step#checkpoint_}))
[ "$step" -lt "$((10#$(basename "$end" .bin | sed 's/checkpoint_//')))" ] ||
  fail "SIGTERM at -np 2 came at step $step, past 0.2 s: a very slow machine?"
mpi 3 run "$tmp/pour.yaml" --out "$tmp/stopped" --resume "$stopped" --until 0.2 --threads 1 > /dev/null 2>&1 ||
  fail "-np 3 resuming the SIGTERM checkpoint"
"$polydem" run "$tmp/pour.yaml" --out "$tmp/stopped/joined" --resume "$tmp/stopped/$(basename "$end")" \
  --until 0.2 --threads 1 > /dev/null 2>&1 || fail "joining the resumed run's final pieces"
/usr/bin/python3 "$here/same_state.py" "$end" "$tmp/stopped/joined/$(basename "$end")" > /dev/null ||
  fail "SIGTERM then -np 3: another final state"
cmp "$tmp/plain200/energy.csv" "$tmp/stopped/energy.csv" || fail "SIGTERM then -np 3: energy.csv differs"
echo "ok: SIGTERM on mpirun -np 2 stopped both ranks at step $step with one checkpoint; -np 3 resumed it to the plain run's bits"
