#!/usr/bin/env bash
# Bodies stored in space order (simulation.body_order: space, the default) or as the scene
# lists them (input): the files name the same bodies by the same ids, the states equal to
# round-off (body_order.py); each order resumes from its checkpoint bit for bit, in the order
# the checkpoint stored, whatever the scene's key or --body-order says.
# usage: body_order.sh PATH/TO/polydem
set -euo pipefail
source "$(dirname "$0")/script_lib.bash" "$1"
source "$here/drop_lib.bash"
for order in space input; do
  "$polydem" run "$tmp/drop.yaml" --out "$tmp/full_$order" --body-order "$order" 2> /dev/null || fail "run $order"
done
# At 40 ms (bodies on the floor and on each other: the sums' order shows, ~1e-15)
python3 "$here/body_order.py" "$tmp/full_space" "$tmp/full_input" 000004 || fail "the two orders' outputs differ"
# Each resumed from its mid-run checkpoint under the other order's key.
for order in space input; do
  other=$([ "$order" = space ] && echo input || echo space)
  mkdir -p "$tmp/resumed_$order"
  "$polydem" run "$tmp/drop.yaml" --out "$tmp/resumed_$order" --resume "$tmp/full_$order/checkpoint_008011.bin" \
      --body-order "$other" 2> /dev/null || fail "resume the $order run"
  cmp "$tmp/full_$order/checkpoint_016023.bin" "$tmp/resumed_$order/checkpoint_016023.bin" ||
    fail "the $order run resumed ends elsewhere"
done
cmp -s "$tmp/full_space/checkpoint_016023.bin" "$tmp/full_input/checkpoint_016023.bin" &&
  fail "the two orders wrote the same file"
echo "body_order: ok"
