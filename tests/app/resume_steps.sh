#!/usr/bin/env bash
# A run stopped at any step and resumed ends as the uninterrupted run, byte for byte (every CSV
# file, all columns, and the final checkpoint): its checkpoint holds the energy ledger's open
# sums (format 07), so the ledger keeps its bits though only the resumed run rebuilds its lists
# at the stop. The drop stopped at every step 1-300 (no contact yet: the clock, the outputs),
# resumed to step 300; then at 24 steps among its impacts (6118-15907, closes and not), resumed
# to its end at 40 ms. ~9 s of CPU.
# usage: resume_steps.sh PATH/TO/polydem
set -euo pipefail
source "$(dirname "$0")/script_lib.bash" "$1"
source "$here/drop_lib.bash"
at_step() { awk -v s="$1" -v dt="$dt" 'BEGIN { printf "%.17g", (s - 0.25) * dt }'; }  # --until ending at step $1 (llround)
same() {  # reference folder, resumed folder, final checkpoint
  for f in "${drop_outputs[@]}" "$3"; do
    cmp -s "$1/$f" "$2/$f" || fail "stopped at step $4: $f differs from the uninterrupted run's"
  done
}
stop_and_resume() {  # step, end (--until), reference folder, final checkpoint
  rm -rf "$tmp/cut"
  "$polydem" run "$tmp/drop.yaml" --out "$tmp/cut" --threads 1 --until "$(at_step "$1")" 2> /dev/null || fail "run to step $1"
  local ck
  ck=$(printf "%s/cut/checkpoint_%06d.bin" "$tmp" "$1")
  [ -f "$ck" ] || fail "no checkpoint at step $1"
  "$polydem" run "$tmp/drop.yaml" --out "$tmp/cut" --threads 1 --resume "$ck" ${2:+--until "$2"} 2> /dev/null ||
    fail "resume at step $1"
  same "$3" "$tmp/cut" "$4" "$1"
}

"$polydem" run "$tmp/drop.yaml" --out "$tmp/full" --threads 1 2> /dev/null || fail "uninterrupted run"
[ -f "$tmp/full/checkpoint_016023.bin" ] || fail "the drop no longer ends at step 16023: $(ls "$tmp/full"/checkpoint_*)"
dt=$(awk -v t="$(tail -1 "$tmp/full/energy.csv" | cut -d, -f1)" 'BEGIN { printf "%.17g", t / 16023 }')  # s, the step
"$polydem" run "$tmp/drop.yaml" --out "$tmp/early" --threads 1 --until "$(at_step 300)" 2> /dev/null || fail "run to 300"
for s in $(seq 1 299); do stop_and_resume "$s" "$(at_step 300)" "$tmp/early" checkpoint_000300.bin; done
for s in 6118 6271 6985 7358 7647 8010 8012 8412 8871 9330 9331 9686 10248 10708 11318 11895 12236 12618 13154 \
  13765 14244 14836 15295 15907; do
  stop_and_resume "$s" "" "$tmp/full" checkpoint_016023.bin
done
echo "resume_steps: 1 passed, 0 failed"
