#!/usr/bin/env bash
# polydem under mpirun: one rank runs as one process; over two ranks, any command but `run`
# stops at once with one message from rank 0 and exit 1, never a hang (`run` over many ranks:
# mpi_run.sh). A build without MPI refuses every command, `run` included, the same way (it
# reads the rank count mpirun sets).
set -euo pipefail
source "$(dirname "$0")/script_lib.bash" "$1"
command -v mpirun > /dev/null || fail "no mpirun: tools/setup.sh installs openmpi-bin"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1  # CI runs as root
expect_timeout=120
refused_once() {  # expected message, then polydem's arguments under two ranks
  local message=$1; shift
  expect_exit 1 "$message" mpirun --oversubscribe -q -np 2 "$polydem" "$@"
  [ "$(cat "$tmp/out" "$tmp/err" | grep -c .)" -eq 1 ] || { cat "$tmp/out" "$tmp/err"; fail "not one message"; }
}
if [ "${POLYDEM_WITH_MPI:-ON}" = OFF ]; then  # CMake sets it; sanitized builds have no MPI
  refused_once "2 MPI ranks: this build has no MPI" check "$here/drop.yaml"
  refused_once "2 MPI ranks: this build has no MPI" run "$here/drop.yaml" --out "$tmp/run"
  [ ! -e "$tmp/run" ] || fail "a refused run wrote $tmp/run"
else
  refused_once "2 MPI ranks: only 'polydem run' runs over many ranks" check "$here/drop.yaml"
fi
expect_exit 0 "chosen time step" mpirun -q -np 1 "$polydem" check "$here/drop.yaml"
echo "ok: mpirun -np 2 refused once with exit 1 (MPI build: ${POLYDEM_WITH_MPI:-ON}), -np 1 runs"
