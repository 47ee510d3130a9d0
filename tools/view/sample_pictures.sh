#!/usr/bin/env bash
# Makes the pictures and plots the samples' READMEs show, from runs already made:
# samples/NAME/pictures/NAME.png (polydem render) and the plots named below (polydem plot).
# usage: tools/view/sample_pictures.sh OUT_ROOT [POLYDEM]   (OUT_ROOT/NAME: the output of sample NAME)
set -euo pipefail
cd "$(dirname "$0")/../.."
root=$1
polydem=${2:-build/polydem}
declare -A plots=([box-fill]="energy" [drum]="angle energy" [hopper]="flow energy" [impact]="driver_impactor energy"
                  [settling]="fluid" [silo]="flow energy" [crosses-drum]="angle energy" [rice]="energy")
declare -A when=([settling]="--time 0.3" [silo]="--time 0.5" [hopper]="" [impact]="" [drum]="" [box-fill]="" [crosses-drum]="" [rice]="")
for name in "${!plots[@]}"; do
  out=$root/$name
  [ -d "$out" ] || { echo "skip $name: no $out"; continue; }
  mkdir -p "samples/$name/pictures"
  # shellcheck disable=SC2086  # `when` holds options
  "$polydem" render "$out" ${when[$name]} --size 400x300 -o "samples/$name/pictures/$name.png"
  "$polydem" plot "$out" -o "$out/plots" > /dev/null
  for p in ${plots[$name]}; do cp "$out/plots/$p.png" "samples/$name/pictures/$p.png"; done
done
