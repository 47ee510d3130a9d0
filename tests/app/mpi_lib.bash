# Shared by the MPI script tests (mpi_run.sh, mpi_pieces.sh), after script_lib.bash:
# `source "$here/mpi_lib.bash"`. Not a test itself: CMake registers *.sh only.
command -v mpirun > /dev/null || fail "no mpirun: tools/setup.sh installs openmpi-bin"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1  # CI runs as root
expect_timeout=240
exec 9>&2  # the test's own stderr: callers send a run's output elsewhere, a failure's tail comes here
mpi() {  # ranks, then polydem's arguments; ranks that wait yield the cores (2 in CI)
  local np=$1 code attempt; shift
  for attempt in 1 2; do
    set +e
    timeout "$expect_timeout" mpirun --oversubscribe -q --mca mpi_yield_when_idle 1 -np "$np" "$polydem" "$@" \
      2> "$tmp/mpi.err"
    code=$?
    set -e
    cat "$tmp/mpi.err" >&2
    # Open MPI failing to start the ranks (no rank printed a 'polydem:' or 'error:' line): once more
    [ "$code" -ne 0 ] && [ "$attempt" = 1 ] && ! grep -q '^polydem:\|^error:' "$tmp/mpi.err" || break
    echo "mpirun -np $np failed (exit $code) before polydem started; once more. It printed:" >&9
    tail -n 20 "$tmp/mpi.err" >&9
  done
  [ "$code" -eq 0 ] || { echo "mpirun -np $np $*: exit $code; its last lines:" >&9; tail -n 20 "$tmp/mpi.err" >&9; }
  return "$code"
}
# The newest checkpoint of a folder: a one-file checkpoint or a manifest, not a piece.
last_checkpoint() { ls "$1"/checkpoint_*.bin | grep -v '_p[0-9]*\.bin$' | sort | tail -1; }
# s, the time of a format-08 checkpoint or manifest 03 (its step x its dt, after the body order),
# or `later` steps on; exact for --until.
checkpoint_time() {  # checkpoint [later]
  /usr/bin/python3 -c "import struct, sys; data = open(sys.argv[1], 'rb').read()
step, dt = struct.unpack_from('<qd', data, 48 + 4 * struct.unpack_from('<Q', data, 40)[0])
print(repr((step + int(sys.argv[2])) * dt))" "$1" "${2:-0}"
}
# A distributed run's checkpoint is a manifest and one piece per rank (sim/checkpoint_pieces.hpp):
# resumed at its own time by one process, it gives back the one-file checkpoint of that state.
joined() {  # scene, checkpoint: prints the one-file checkpoint of the same state
  local dir="$(dirname "$2")/joined"
  if [ "$(head -c 8 "$2")" = PDCKMA03 ]; then
    rm -rf "$dir"
    "$polydem" run "$1" --out "$dir" --resume "$2" --until "$(checkpoint_time "$2")" --threads 1 > /dev/null 2>&1 ||
      fail "$2: cannot join the pieces" >&2
    echo "$dir/$(basename "$2")"
  else echo "$2"
  fi
}
# The same final state (joined if in pieces) and the same CSV files, byte for byte.
same_outputs() {  # reference folder, other folder, scene
  local f
  local final=$(joined "$3" "$2/$(basename "$(last_checkpoint "$1")")")
  /usr/bin/python3 "$here/same_state.py" "$(last_checkpoint "$1")" "$final" > /dev/null || fail "$2: final state differs"
  for f in "$1"/*.csv; do
    cmp "$f" "$2/$(basename "$f")" || fail "$2: $(basename "$f") differs"
  done
}
