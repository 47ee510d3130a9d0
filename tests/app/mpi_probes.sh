#!/usr/bin/env bash
# Probes under mpirun: a flow probe across the pour's slabs (the bodies past a plane, their
# mass and rate) and a repose-angle probe in the turning drum (the highest centre per column)
# write the same CSV bytes at -np 2 and 3 as one plain process. Each rank measures its own
# bodies and rank 0 meets the parts (the bodies past the plane by id, each column's top): at
# -np 2 rank 1 sends 2-6 B a step of collectives for a probe (a row every 80-124 steps),
# where gathering its bodies' state for it sent 96-154 (asserted below 40).
set -euo pipefail
source "$(dirname "$0")/script_lib.bash" "$1"
source "$here/mpi_lib.bash"
scene_with() {  # name, probe line or "": the scene with its shapes found from $tmp, the probe added
  sed -e "s|\.\./\.\./shapes|$here/../../shapes|" -e '/checkpoint_every/d' "$here/mpi_$1.yaml" > "$tmp/mpi_$1.yaml"
  [ -z "$2" ] || printf '  probes:\n    - %s\n' "$2" >> "$tmp/mpi_$1.yaml"
}
own_bytes() { sed -n 's/.*rank 1 of 2: holds.* \([0-9.e+]*\) bytes of its own.*/\1/p' "$1"; }  # a step, in collectives
for scene in 'pour|past|flow: {name: past, point: [0.02, 0, 0], normal: [1, 0, 0]}' \
             'drum|angle|repose_angle: {name: angle, driver: drum, column: "1 cm", fit: 0.8}'; do
  IFS='|' read -r name probe line <<< "$scene"
  scene_with "$name" "$line"
  "$polydem" run "$tmp/mpi_$name.yaml" --out "$tmp/$name" --threads 1 > /dev/null 2>&1 || fail "plain $name run"
  [ "$(wc -l < "$tmp/$name/$probe.csv")" -gt 30 ] || fail "$name: $probe.csv has too few rows"
  for np in 2 3; do
    POLYDEM_MPI_COUNTS=1 mpi "$np" run "$tmp/mpi_$name.yaml" --out "$tmp/$name$np" --threads 1 > /dev/null \
      2> "$tmp/$name$np.err" || fail "$name at -np $np"
    cmp "$tmp/$name/$probe.csv" "$tmp/$name$np/$probe.csv" || fail "$name: $probe.csv differs at -np $np"
  done
  scene_with "$name" ""
  POLYDEM_MPI_COUNTS=1 mpi 2 run "$tmp/mpi_$name.yaml" --out "$tmp/${name}bare" --threads 1 > /dev/null \
    2> "$tmp/${name}bare.err" || fail "$name without its probe at -np 2"
  extra=$(python3 -c "print(round($(own_bytes "$tmp/${name}2.err") - $(own_bytes "$tmp/${name}bare.err"), 1))")
  python3 -c "import sys; sys.exit(not $extra < 40)" || fail "$name: the probe costs rank 1 $extra collective bytes a step"
  echo "ok: $name: $probe.csv at -np 2 and 3 is the plain run's, byte for byte; rank 1 sends $extra B a step for it"
done
