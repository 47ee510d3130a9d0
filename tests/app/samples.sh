#!/usr/bin/env bash
# Every sample loads (`check`) and runs its first 10 ms: exit 0, a checkpoint at the end, and
# energy.csv rows with finite values whose time never goes back and ends at 10 ms (every csv_every divides it).
set -euo pipefail
source "$(dirname "$0")/script_lib.bash" "$1"
count=0
for scene in "$here"/../../samples/*/scene*.yaml; do
  name="$(basename "$(dirname "$scene")")/$(basename "$scene")"
  "$polydem" check "$scene" > "$tmp/check.log" 2>&1 || { cat "$tmp/check.log"; fail "$name: check"; }
  grep -q ": valid" "$tmp/check.log" || fail "$name: check did not say valid"
  [ "$(basename "$scene")" = scene.yaml ] || continue  # the silo's other orifices: check only
  out="$tmp/$(basename "$(dirname "$scene")")"
  "$polydem" run "$scene" --out "$out" --until "10 ms" --threads 2 > "$tmp/run.log" 2>&1 ||
    { tail -5 "$tmp/run.log"; fail "$name: run --until 10 ms"; }
  ls "$out"/checkpoint_*.bin > /dev/null 2>&1 || fail "$name: no checkpoint at --until"
  awk -F, 'NR == 1 { next }
           { for (i = 1; i <= NF; ++i) if ($i !~ /^-?[0-9.]+(e[-+]?[0-9]+)?$/) { print "not finite: " $0; exit 1 }
             if ($1 + 0 < last) { print "time goes back: " $0; exit 1 } last = $1 + 0; rows++ }
           END { if (rows < 1 || rows < 2 || last < 0.0099 || last > 0.0101) { print rows " rows, last time " last; exit 1 } }' \
    "$out/energy.csv" || fail "$name: energy.csv"
  count=$((count + 1))
done
[ "$count" -ge 6 ] || fail "only $count samples ran"
echo "samples: $count run, all checked"
