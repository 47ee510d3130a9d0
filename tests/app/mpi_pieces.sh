#!/usr/bin/env bash
# A distributed run writes in parallel (issue 20): each rank its bodies' and contacts' VTK
# pieces, with a .pvtu and a .pvtp that scene.pvd names, so ParaView opens the run as one data
# set equal to one process's files (tests/app/check_pieces.py); each rank its checkpoint piece,
# with a manifest, resumed on another rank count or in one process on the plain run's bits,
# also after SIGTERM on mpirun.
set -euo pipefail
source "$(dirname "$0")/script_lib.bash" "$1"
source "$here/mpi_lib.bash"
# The pour with a frame every 10 ms (5 frames; the first before any step, all bodies on rank 0).
sed -e 's|vtk_every: "20 ms"|vtk_every: "10 ms"|' -e "s|../../shapes|$here/../../shapes|" "$here/mpi_pour.yaml" \
  > "$tmp/pour.yaml"
"$polydem" run "$tmp/pour.yaml" --out "$tmp/plain" --threads 1 > /dev/null 2>&1 || fail "plain pour"
for np in 2 3; do
  mpi "$np" run "$tmp/pour.yaml" --out "$tmp/np$np" --threads 1 > /dev/null 2>&1 || fail "pour at -np $np"
  /usr/bin/python3 "$here/check_pieces.py" "$tmp/plain" "$tmp/np$np" "$np" || fail "-np $np: VTK pieces"
done
echo "ok: -np 2, 3: .pvtu, .pvtp and a piece per rank, together the one-process bodies and contacts files"
"$polydem" render "$tmp/np2" -o "$tmp/np2.png" > /dev/null 2>&1 || fail "polydem render of the -np 2 pieces"
[ -s "$tmp/np2.png" ] || fail "polydem render wrote no picture of the -np 2 pieces"
echo "ok: polydem render draws the -np 2 run from its .pvtu files"

# Checkpoints in parallel: a manifest and a piece per rank. The -np 2 run's 20 ms checkpoint
# resumed by one process ends on the plain run's state and CSV files (the -np 3 resume:
# mpi_run.sh); so does the -np 2 final checkpoint, joined by one process resuming it at its time.
mid=$tmp/np2/checkpoint_002533.bin
for f in "$mid" "${mid%.bin}_p0.bin" "${mid%.bin}_p1.bin"; do [ -s "$f" ] || fail "no $f"; done
[ "$(head -c 8 "$mid")" = PDCKMA03 ] || fail "$mid is not a manifest"
cp -r "$tmp/np2" "$tmp/one"
rm "$tmp/one"/checkpoint_005067*.bin
"$polydem" run "$tmp/pour.yaml" --out "$tmp/one" --resume "$tmp/one/checkpoint_002533.bin" --threads 1 \
  > /dev/null 2>&1 || fail "one process resuming the -np 2 pieces"
/usr/bin/python3 "$here/same_state.py" "$tmp/plain/checkpoint_005067.bin" "$tmp/one/checkpoint_005067.bin" > /dev/null ||
  fail "-np 2 pieces resumed by one process: another final state"
for f in energy.csv driver_floor.csv driver_left.csv; do
  cmp "$tmp/plain/$f" "$tmp/one/$f" || fail "-np 2 pieces resumed by one process: $f differs"
  cmp "$tmp/plain/$f" "$tmp/np2/$f" || fail "-np 2: $f differs from one process's"
done
/usr/bin/python3 "$here/same_state.py" "$tmp/plain/checkpoint_005067.bin" \
  "$(joined "$tmp/pour.yaml" "$tmp/np2/checkpoint_005067.bin")" > /dev/null || fail "-np 2: another final state"
echo "ok: -np 2 checkpoint pieces resume in one process on the plain run's bits, CSV files included"

# A missing, damaged or foreign piece: one message naming the manifest, the piece and its file,
# exit 1 on every rank (-np 2, no hang) or in one process.
broken() {  # what to do to the copy's 20 ms checkpoint, expected message, ranks (0: one process)
  rm -rf "$tmp/broken" && cp -r "$tmp/np2" "$tmp/broken"
  (cd "$tmp/broken" && eval "$1")
  local run=("$polydem" run "$tmp/pour.yaml" --out "$tmp/broken" --resume "$tmp/broken/checkpoint_002533.bin")
  if [ "$3" = 0 ]; then expect_exit 1 "$2" "${run[@]}"
  else expect_exit 1 "$2" mpirun --oversubscribe -q --mca mpi_yield_when_idle 1 -np "$3" "${run[@]}"
  fi
  [ "$(grep -c "error:" "$tmp/err")" -eq 1 ] || { cat "$tmp/err"; fail "not one message"; }
}
broken "rm checkpoint_002533_p1.bin" "checkpoint_002533.bin: piece 1 of 2 (.*checkpoint_002533_p1.bin) is missing" 2
broken "printf x | dd of=checkpoint_002533_p0.bin bs=1 seek=100 conv=notrunc status=none" \
  "piece 0 of 2 .* is damaged: .*checksum mismatch" 0
broken "cp checkpoint_005067_p0.bin checkpoint_002533_p0.bin" "piece 0 of 2 .* is not the piece the manifest names" 0
echo "ok: a missing, damaged or foreign checkpoint piece: one message naming it, exit 1"

# SIGTERM on mpirun (as Ctrl-C or a batch scheduler's stop): every rank stops at the same step
# (the signal is ORed over the ranks each step) and one checkpoint is written, a manifest and
# its pieces. OpenMPI's mpirun passes the signal on some odls_base_sigkill_timeout s later and
# kills the ranks as long after that (README), so the step varies with the machine: the
# reference is the run's own periodic checkpoint before it (or the start), which one process
# takes to the stopped step (the stopped checkpoint's state) and 20 ms on, where -np 3 resuming
# the stopped checkpoint must end too. timeout --foreground passes mpirun the signal once (its
# process group would get it again, and a second one makes mpirun quit at once, ranks orphaned).
timeout --foreground "$expect_timeout" mpirun --oversubscribe -q --mca mpi_yield_when_idle 1 \
  --mca odls_base_sigkill_timeout 5 -np 2 "$polydem" run "$tmp/pour.yaml" --out "$tmp/stopped" --until 5 --threads 1 \
  > /dev/null 2> "$tmp/stopped.err" &
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
[ "$(head -c 8 "$stopped")" = PDCKMA03 ] && [ -s "${stopped%.bin}_p0.bin" ] && [ -s "${stopped%.bin}_p1.bin" ] ||
  fail "SIGTERM at -np 2: no manifest and pieces at $stopped"
step=$(basename "$stopped" .bin); step=$((10#${step#checkpoint_}))
before=
for f in $(ls "$tmp/stopped"/checkpoint_*.bin | grep -v '_p[0-9]*\.bin$' | sort); do [ "$f" = "$stopped" ] && break; before=$f; done
cp -r "$tmp/stopped" "$tmp/ref"
rm "$tmp/ref/$(basename "$stopped")"
"$polydem" run "$tmp/pour.yaml" --out "$tmp/ref" ${before:+--resume "$tmp/ref/$(basename "$before")"} \
  --until "$(checkpoint_time "$stopped")" --threads 1 > /dev/null 2>&1 || fail "one process to the stopped step"
joined=$(joined "$tmp/pour.yaml" "$stopped")
/usr/bin/python3 "$here/same_state.py" "$tmp/ref/$(basename "$stopped")" "$joined" > /dev/null ||
  fail "SIGTERM at -np 2: the checkpoint at step $step is not the run's state there"
later=$(checkpoint_time "$stopped" 2533)
"$polydem" run "$tmp/pour.yaml" --out "$tmp/ref" --resume "$tmp/ref/$(basename "$stopped")" --until "$later" \
  --threads 1 > /dev/null 2>&1 || fail "one process 20 ms on"
mpi 3 run "$tmp/pour.yaml" --out "$tmp/stopped" --resume "$stopped" --until "$later" --threads 1 > /dev/null 2>&1 ||
  fail "-np 3 resuming the SIGTERM checkpoint"
end=$(last_checkpoint "$tmp/ref")
/usr/bin/python3 "$here/same_state.py" "$end" "$(joined "$tmp/pour.yaml" "$tmp/stopped/$(basename "$end")")" \
  > /dev/null || fail "SIGTERM then -np 3: another state 20 ms on"
cmp "$tmp/ref/energy.csv" "$tmp/stopped/energy.csv" || fail "SIGTERM then -np 3: energy.csv differs"
echo "ok: SIGTERM on mpirun -np 2 stopped both ranks at step $step with one checkpoint of the run's state; -np 3 resumed it to one process's bits 20 ms on"
