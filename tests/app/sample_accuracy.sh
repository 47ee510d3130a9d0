#!/usr/bin/env bash
# Issue 16: each sample's README states the restitution error of its impacts at its step, as
# `polydem check` prints it for the sample's scene (scene.yaml, else its one scene_*.yaml):
# "At its step (F x critical) this scene's impacts rebound within P% of en." (P = 100 x the
# printed error, 2 significant digits; line breaks anywhere). Fails when a README goes stale.
set -euo pipefail
source "$(dirname "$0")/script_lib.bash" "$1"
count=0
for readme in "$here"/../../samples/*/README.md; do
  dir=$(dirname "$readme") name=$(basename "$(dirname "$readme")")
  scene="$dir/scene.yaml"
  [ -f "$scene" ] || scene=$(ls "$dir"/scene_*.yaml | head -1)
  "$polydem" check "$scene" > "$tmp/check.log" 2>&1 || { cat "$tmp/check.log"; fail "$name: check"; }
  fraction=$(sed -n 's/^chosen time step: .*(\([0-9.e+-]*\) x critical).*/\1/p' "$tmp/check.log")
  error=$(sed -n 's/^ *expected restitution error of an impact at this step: \([0-9.e+-]*\) .*/\1/p' "$tmp/check.log")
  [ -n "$fraction" ] && [ -n "$error" ] || { cat "$tmp/check.log"; fail "$name: no step fraction or expected error"; }
  percent=$(awk -v e="$error" 'BEGIN { printf "%.2g", 100 * e }')
  line="At its step ($fraction x critical) this scene's impacts rebound within $percent% of en."
  tr -s ' \n' '  ' < "$readme" | grep -qF "$line" || fail "$name/README.md does not say: $line"
  count=$((count + 1))
done
[ "$count" -ge 9 ] || fail "only $count sample READMEs"
echo "sample READMEs: $count state their error at their step as polydem check prints it"
