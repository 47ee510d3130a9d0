#!/usr/bin/env bash
# Resuming after a run was cut short: the CSV files (energy, drivers, probes) and scene.pvd end
# with the same rows as an uninterrupted run (rows written after the checkpoint are dropped,
# a half-written last line too); SIGTERM writes a checkpoint and exits 3; another scene's
# checkpoint is refused unless --force; a checkpoint past the end of the run is refused; one at
# its very end is written again as it was.
# usage: resume.sh PATH/TO/polydem
set -euo pipefail
source "$(dirname "$0")/script_lib.bash" "$1"
source "$here/drop_lib.bash"
same_outputs() {  # same_outputs DIR_A DIR_B: every CSV and the .pvd identical
  for f in "${drop_outputs[@]}"; do
    cmp "$1/$f" "$2/$f" || fail "$f differs between $1 and $2"
  done
}

"$polydem" run "$tmp/drop.yaml" --out "$tmp/full" 2> /dev/null || fail "uninterrupted run"
[ "$(wc -l < "$tmp/full/energy.csv")" -eq 42 ] || fail "energy.csv of the full run: $(wc -l < "$tmp/full/energy.csv") lines, expected 42"

# A run killed (SIGKILL) after its rows to 40 ms but with its last checkpoint at 20 ms, the
# last row of energy.csv half written: resumed, it ends as the uninterrupted run.
cp -r "$tmp/full" "$tmp/killed"
rm "$tmp/killed/checkpoint_016023.bin"
head -c -20 "$tmp/full/energy.csv" > "$tmp/killed/energy.csv"
"$polydem" run "$tmp/drop.yaml" --out "$tmp/killed" --resume "$tmp/killed/checkpoint_008011.bin" 2> /dev/null || fail "resume"
same_outputs "$tmp/full" "$tmp/killed"
cmp "$tmp/full/checkpoint_016023.bin" "$tmp/killed/checkpoint_016023.bin" || fail "final state differs"

# SIGTERM: a checkpoint, exit code 3; resumed, the same rows and state as the full run.
sed "s/duration: \"40 ms\"/duration: \"400 ms\"/" "$tmp/drop.yaml" > "$tmp/long.yaml"
"$polydem" run "$tmp/long.yaml" --out "$tmp/long" 2> /dev/null || fail "long run"
"$polydem" run "$tmp/long.yaml" --out "$tmp/term" --threads 1 2> "$tmp/term.log" &
sigterm_after_rows $! "$tmp/term" "$tmp/term.log"  # sets resume
"$polydem" run "$tmp/long.yaml" --out "$tmp/term" --resume "$resume" 2> /dev/null || fail "resume after SIGTERM"
same_outputs "$tmp/long" "$tmp/term"

# The same stop made repeatable: a run ended (--until 6099.5 dt: step 6100), a ledger close where no
# checkpoint is due (the step a SIGTERM near 23 ms stops at), resumed: the same rows as the full run.
steps=$(basename "$(ls "$tmp/long"/checkpoint_*.bin | tail -1)" .bin); steps=$((10#${steps#checkpoint_}))
t_end=$(tail -1 "$tmp/long/energy.csv" | cut -d, -f1)  # s, at step $steps
until_t=$(awk -v t="$t_end" -v n="$steps" 'BEGIN { printf "%.17g", 6099.5 * t / n }')
"$polydem" run "$tmp/long.yaml" --out "$tmp/cut" --until "$until_t" 2> /dev/null || fail "run to step 6100"
[ -f "$tmp/cut/checkpoint_006100.bin" ] || fail "no checkpoint at step 6100: $(ls "$tmp/cut"/checkpoint_*)"
"$polydem" run "$tmp/long.yaml" --out "$tmp/cut" --resume "$tmp/cut/checkpoint_006100.bin" 2> /dev/null || fail "resume at 6100"
same_outputs "$tmp/long" "$tmp/cut"

# Another scene (gravity upwards, same bodies and step): refused, or resumed with --force.
sed "s/gravity: \[0, 0, -9.807\]/gravity: [0, 0, 9.807]/" "$tmp/drop.yaml" > "$tmp/up.yaml"
set +e; "$polydem" run "$tmp/up.yaml" --out "$tmp/up" --resume "$tmp/full/checkpoint_008011.bin" 2> "$tmp/up.log"; code=$?; set -e
[ "$code" -eq 1 ] || fail "another scene's checkpoint: exit $code, expected 1"
grep -q "checkpoint_008011.bin: checkpoint written for another scene.*--force" "$tmp/up.log" || { cat "$tmp/up.log"; fail "no refusal message"; }
"$polydem" run "$tmp/up.yaml" --out "$tmp/up" --resume "$tmp/full/checkpoint_008011.bin" --force 2> "$tmp/up.log" || fail "--force"
grep -q "warning: .*another scene.*resuming anyway (--force)" "$tmp/up.log" || { cat "$tmp/up.log"; fail "no --force warning"; }
# Moved or resized drivers are another scene too (the wall's point, the box's width).
sed "s/name: left, point: \[-0.035, 0, 0\]/name: left, point: [-0.036, 0, 0]/" "$tmp/drop.yaml" > "$tmp/wide.yaml"
grep -q "point: \[-0.036" "$tmp/wide.yaml" || fail "wide.yaml: the wall did not move"
set +e; "$polydem" run "$tmp/wide.yaml" --out "$tmp/wide" --resume "$tmp/full/checkpoint_008011.bin" 2> "$tmp/wide.log"; code=$?; set -e
[ "$code" -eq 1 ] && grep -q "written for another scene" "$tmp/wide.log" || { cat "$tmp/wide.log"; fail "a moved wall: exit $code"; }
# A checkpoint past the end of the run.
set +e; "$polydem" run "$tmp/drop.yaml" --out "$tmp/past" --until 0.01 --resume "$tmp/full/checkpoint_008011.bin" 2> "$tmp/past.log"; code=$?; set -e
[ "$code" -eq 1 ] && grep -q "past the end of this run" "$tmp/past.log" || { cat "$tmp/past.log"; fail "checkpoint past the end: exit $code"; }
# A checkpoint at the very end of the run (no step left, as when joining a distributed run's
# pieces into one file): the run writes it again, byte for byte. Spheres only: their list keeps
# contact records only for the steps whose state is written, and the checkpoint needs them.
sed -e "s/- shape: cube/- shape: sphere/" -e "s/{cube: 0.5, sphere: 0.25, octahedron: 0.25}/{sphere: 1}/" \
  "$tmp/drop.yaml" > "$tmp/balls.yaml"
"$polydem" run "$tmp/balls.yaml" --out "$tmp/balls" 2> /dev/null || fail "spheres to 40 ms (touching at the end)"
final=$(ls "$tmp"/balls/checkpoint_*.bin | sort | tail -1)
"$polydem" run "$tmp/balls.yaml" --out "$tmp/again" --resume "$final" 2> "$tmp/again.log" ||
  { cat "$tmp/again.log"; fail "resumed with no step left"; }
cmp "$final" "$tmp/again/$(basename "$final")" || fail "no step left: the checkpoint written again differs"
echo "resume: 1 passed, 0 failed"
