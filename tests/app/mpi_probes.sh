#!/usr/bin/env bash
# Probes under mpirun: a flow probe across the pour's slabs (the bodies past a plane, their
# mass and rate) and a repose-angle probe in the turning drum (the highest centre per column)
# write the same CSV bytes at -np 2 and 3 as one plain process (they read the state gathered
# to rank 0, in global id order).
set -euo pipefail
source "$(dirname "$0")/script_lib.bash" "$1"
source "$here/mpi_lib.bash"
with_probe() {  # scene, probe line: the scene with its shapes found from $tmp and the probe added
  sed -e "s|\.\./\.\./shapes|$here/../../shapes|" -e '/checkpoint_every/d' "$here/$1" > "$tmp/$1"
  printf '  probes:\n    - %s\n' "$2" >> "$tmp/$1"
}
with_probe mpi_pour.yaml 'flow: {name: past, point: [0.02, 0, 0], normal: [1, 0, 0]}'
with_probe mpi_drum.yaml 'repose_angle: {name: angle, driver: drum, column: "1 cm", fit: 0.8}'
for scene in pour:past drum:angle; do
  name=${scene%%:*} probe=${scene#*:}
  "$polydem" run "$tmp/mpi_$name.yaml" --out "$tmp/$name" --threads 1 > /dev/null 2>&1 || fail "plain $name run"
  [ "$(wc -l < "$tmp/$name/$probe.csv")" -gt 30 ] || fail "$name: $probe.csv has too few rows"
  for np in 2 3; do
    mpi "$np" run "$tmp/mpi_$name.yaml" --out "$tmp/$name$np" --threads 1 > /dev/null 2>&1 || fail "$name at -np $np"
    cmp "$tmp/$name/$probe.csv" "$tmp/$name$np/$probe.csv" || fail "$name: $probe.csv differs at -np $np"
  done
  echo "ok: $name: $probe.csv at -np 2 and 3 is the plain run's, byte for byte"
done
