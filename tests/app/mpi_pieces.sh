#!/usr/bin/env bash
# A distributed run writes in parallel (issue 20): each rank its bodies' VTK piece, with a
# .pvtu that scene.pvd names, so ParaView opens the run as one data set equal to one
# process's bodies files (tests/app/check_pieces.py).
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
