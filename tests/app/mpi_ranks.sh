#!/usr/bin/env bash
# polydem under mpirun: one rank runs as one process; two ranks stop at once with one message
# from rank 0 and exit 1 (a scene over many ranks is issue 20's next step), never a hang. A
# build without MPI refuses the same way (it reads the rank count mpirun sets).
set -euo pipefail
source "$(dirname "$0")/script_lib.bash" "$1"
command -v mpirun > /dev/null || fail "no mpirun: tools/setup.sh installs openmpi-bin"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1  # CI runs as root
expect_timeout=120
expect_exit 1 "2 MPI ranks: polydem runs a scene on one rank so far" \
  mpirun --oversubscribe -q -np 2 "$polydem" run "$here/drop.yaml" --out "$tmp/two"
[ "$(cat "$tmp/out" "$tmp/err" | grep -c .)" -eq 1 ] || { cat "$tmp/out" "$tmp/err"; fail "not one message"; }
[ ! -e "$tmp/two" ] || fail "two ranks wrote an output folder"
expect_exit 0 "chosen time step" mpirun -q -np 1 "$polydem" check "$here/drop.yaml"
echo "ok: mpirun -np 2 refused once with exit 1, -np 1 runs"
