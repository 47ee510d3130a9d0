#!/usr/bin/env bash
# Issue 20's scenes over 1-4 MPI ranks give one process's bits: the box-fill sample (2,000
# mixed polyhedra raining into a walled box), the drum sample (a rotating cylinder) and an STL
# hopper pressed by a servo lid (mpi_hopper.yaml: the lid's load is the reactions of every
# rank). Each ends, at -np 1 (2 threads), 2, 3 and 4, on the plain run's final state with its
# CSV files (energy, drivers, probes) byte for byte; the hopper's -np 2 checkpoint at 50 ms
# resumed with -np 4 and in one process without MPI ends there too.
set -euo pipefail
source "$(dirname "$0")/script_lib.bash" "$1"
source "$here/mpi_lib.bash"
samples="$here/../../samples"

over_ranks() {  # name, scene, polydem's extra arguments...: -np 1-4 against the plain run
  local name=$1 scene=$2 np threads; shift 2
  "$polydem" run "$scene" --out "$tmp/$name" --threads 1 "$@" > /dev/null 2>&1 || fail "plain $name run"
  for np in 1 2 3 4; do
    threads=$((np == 1 ? 2 : 1))
    mpi "$np" run "$scene" --out "$tmp/$name$np" --threads "$threads" "$@" > /dev/null 2>&1 ||
      fail "$name at -np $np"
    same_outputs "$tmp/$name" "$tmp/$name$np" "$scene"
  done
  echo "ok: $name: -np 1, 2, 3, 4 give the plain run's bits"
}

over_ranks box-fill "$samples/box-fill/scene.yaml" --until 0.1
over_ranks drum "$samples/drum/scene.yaml" --until 0.05
over_ranks hopper "$here/mpi_hopper.yaml"
pressed=$(awk -F, 'NR > 1 && $4 > 0 { n++ } END { print n + 0 }' "$tmp/hopper/driver_lid.csv")
[ "$pressed" -ge 5 ] || fail "the lid pressed on the bodies in $pressed of its rows"  # 5 ms rows

# The -np 2 checkpoint at 50 ms, resumed with -np 4 and by a plain run (no MPI initialised).
half="$tmp/hopper2/checkpoint_001250.bin"  # 1,250 steps of 40 us
[ -e "$half" ] && [ "$(checkpoint_time "$half")" = 0.05 ] || fail "no -np 2 checkpoint at 50 ms"
for np in 4 plain; do
  cp -r "$tmp/hopper2" "$tmp/resumed$np"
  last=$(last_checkpoint "$tmp/resumed$np")
  rm -f "$last" "${last%.bin}"_p*.bin  # the resumed run writes its own final checkpoint
  args=(run "$here/mpi_hopper.yaml" --out "$tmp/resumed$np" --resume "$tmp/resumed$np/$(basename "$half")" --threads 1)
  if [ "$np" = plain ]; then "$polydem" "${args[@]}" > /dev/null 2>&1 || fail "resume in one process"
  else mpi "$np" "${args[@]}" > /dev/null 2>&1 || fail "resume with -np $np"
  fi
  same_outputs "$tmp/hopper" "$tmp/resumed$np" "$here/mpi_hopper.yaml"
done
echo "ok: the hopper's -np 2 checkpoint at 50 ms resumed with -np 4 and in one process gives the plain run's bits"
