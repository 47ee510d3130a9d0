#!/usr/bin/env bash
# A time step far above the critical one: the run must stop with exit code 2, name the body,
# the step and the likely cause, and leave the last good state on disk; a warning comes first.
set -euo pipefail
polydem=$1
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
sed -e "s|dt: auto|dt: \"2 ms\"|" -e "s|duration: \"40 ms\"|duration: \"5 s\"|" -e "s|../../shapes|$here/../../shapes|" "$here/drop.yaml" > "$tmp/blowup.yaml"
set +e
"$polydem" run "$tmp/blowup.yaml" --out "$tmp/out" > "$tmp/log" 2>&1
code=$?
set -e
cat "$tmp/log" | tail -3
[ "$code" -eq 2 ] || { echo "FAIL: exit code $code, expected 2"; exit 1; }
grep -q "warning: dt = " "$tmp/log" || { echo "FAIL: no warning about the time step"; exit 1; }
grep -q "body [0-9]* (shape '[a-z]*') became non-finite by step [0-9]*" "$tmp/log" || { echo "FAIL: body and step not named"; exit 1; }
grep -q "critical step" "$tmp/log" || { echo "FAIL: cause not named"; exit 1; }
[ -s "$tmp/out/bodies_last_good.vtu" ] || { echo "FAIL: last good state not written"; exit 1; }
echo "blowup: 1 passed, 0 failed"
