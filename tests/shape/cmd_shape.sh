#!/usr/bin/env bash
# `polydem shape hull` then `shape info --json`: counts, Steiner volume of a rounded cube, exit codes.
# usage: tests/shape/cmd_shape.sh PATH/TO/polydem
set -euo pipefail
polydem=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
printf '# unit cube and an inside point\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n0.5 0.5 0.5\n' > "$dir/cube.txt"
"$polydem" shape hull "$dir/cube.txt" --radius "100 mm" --name cube -o "$dir/lib.shp" > /dev/null
"$polydem" shape info "$dir/lib.shp" --json > "$dir/info.json"
/usr/bin/python3 - "$dir/info.json" <<'PY'
import json, math, sys
s = json.load(open(sys.argv[1]))[0]
r = 0.1
assert (s["nv"], s["ne"], s["nf"]) == (8, 12, 6), s
steiner = 1 + 6 * r + 3 * math.pi * r * r + 4 / 3 * math.pi * r ** 3
assert abs(s["volume"] - steiner) < 1e-12 * steiner, (s["volume"], steiner)
assert all(abs(c - 0.5) < 1e-12 for c in s["center"]), s["center"]
PY
# Bad input: exit code 1 and one line on stderr.
set +e
"$polydem" shape hull "$dir/cube.txt" --radius "-1 mm" --name bad -o "$dir/bad.shp" 2> "$dir/err.txt"
code=$?
set -e
[ "$code" -eq 1 ] || { echo "expected exit 1 for a negative radius, got $code"; exit 1; }
[ "$(wc -l < "$dir/err.txt")" -eq 1 ] || { echo "expected one error line:"; cat "$dir/err.txt"; exit 1; }
echo "cmd_shape: ok"
