#!/usr/bin/env bash
# End-to-end checks of the command line: exit codes, errors, a real run read back with VTK,
# and a resumed run that ends on the same bits as an uninterrupted one.
# usage: cli.sh PATH/TO/polydem
set -euo pipefail
source "$(dirname "$0")/script_lib.bash" "$1"

expect_exit 0 "usage" "$polydem" --help
expect_exit 0 "resume" "$polydem" run --help
expect_exit 1 "unknown command" "$polydem" frobnicate
expect_exit 1 "nothere.yaml" "$polydem" run "$tmp/nothere.yaml"

# A misspelled key: file, line and the suggestion.
cp "$here/drop.yaml" "$tmp/bad.yaml"
sed -i 's/^  seed: 3/  seeed: 3/' "$tmp/bad.yaml"
sed -i "s|../../shapes|$here/../../shapes|" "$tmp/bad.yaml"
expect_exit 1 "bad.yaml:5" "$polydem" check "$tmp/bad.yaml"
expect_exit 1 "seed" "$polydem" check "$tmp/bad.yaml"

expect_exit 0 "critical time step" "$polydem" check "$here/drop.yaml"
# dt: auto for polyhedra is the step of 1e-3 by the cube landings' rows (sim/step_accuracy.cpp),
# 0.0654 x critical (not the spheres' exact step's 0.181); polydem check prints the largest error
# measured there of the cases that bound the scene's impacts: the cube landings and, with
# friction, the oblique impact (6.9e-4 there); accuracy: 1e-3 inverts the same model.
expect_exit 0 "(0.0654 x critical) \[auto\]" "$polydem" check "$here/drop.yaml"
grep -q "expected restitution error of an impact at this step: 1.0e-03 (0.0654 x critical; cube landings, oblique impact)" "$tmp/out" \
  || { cat "$tmp/out"; fail "check: no expected error at dt: auto"; }
sed "s|^  dt: auto|  dt: auto\n  accuracy: 1e-3|; s|\.\./\.\./shapes|$here/../../shapes|" "$here/drop.yaml" > "$tmp/accuracy.yaml"
expect_exit 0 "(0.0654 x critical) \[auto, accuracy\]" "$polydem" check "$tmp/accuracy.yaml"
grep -q "expected restitution error of an impact at this step: 1.0e-03 (0.0654 x critical" "$tmp/out" \
  || { cat "$tmp/out"; fail "check: accuracy 1e-3 not met"; }

# Spheres under the linear law take its exact step: dt: auto is that model's step for 1e-3 of
# the restitution; with friction the oblique impact's 3.8e-3 there is printed.
expect_exit 0 "(0.181 x critical) \[auto\]" "$polydem" check "$here/../../tools/bench/spheres.yaml"
grep -q "expected restitution error of an impact at this step: 3.8e-03 (0.181 x critical; exact-step sphere-wall impacts, oblique impact)" "$tmp/out" \
  || { cat "$tmp/out"; fail "check: spheres not on the exact step's model"; }

# A full run, then the same run in two halves through a checkpoint.
"$polydem" run "$here/drop.yaml" --out "$tmp/full" --threads 2 2> "$tmp/full.log" || { cat "$tmp/full.log"; fail "run"; }
grep -q "dt = .* s (expected restitution error of an impact at this step: 1.0e-03 (0.0654 x critical; cube landings, oblique impact))" "$tmp/full.log" \
  || { cat "$tmp/full.log"; fail "run: no expected error on the start-up line"; }
"$polydem" run "$here/drop.yaml" --out "$tmp/half" --threads 1 --until 0.02 2> /dev/null
"$polydem" run "$here/drop.yaml" --out "$tmp/half" --threads 2 --resume "$(ls "$tmp"/half/checkpoint_*.bin | sort | tail -1)" 2> /dev/null
last_full=$(ls "$tmp"/full/checkpoint_*.bin | sort | tail -1)
last_half=$(ls "$tmp"/half/checkpoint_*.bin | sort | tail -1)
[ "$(basename "$last_full")" = "$(basename "$last_half")" ] || fail "runs ended at different steps"
cmp "$last_full" "$last_half" || fail "resumed run differs from the uninterrupted one"
cmp <(cut -d, -f1-7 "$tmp/full/energy.csv") <(cut -d, -f1-7 "$tmp/half/energy.csv") || fail "energy.csv differs after resume"

# Ctrl-C: the run stops at the end of a step with a checkpoint, and resuming from it ends on
# the same bits as the uninterrupted run. The scene runs 10x longer here, so the interrupt
# always lands before its end however fast the machine.
sed "s/duration: \"40 ms\"/duration: \"400 ms\"/" "$here/drop.yaml" > "$tmp/long.yaml"
sed -i "s|\.\./\.\./shapes|$here/../../shapes|" "$tmp/long.yaml"
"$polydem" run "$tmp/long.yaml" --out "$tmp/long" --threads 2 2> /dev/null || fail "long run"
last_long=$(ls "$tmp"/long/checkpoint_*.bin | sort | tail -1)
"$polydem" run "$tmp/long.yaml" --out "$tmp/int" --threads 1 2> "$tmp/int.log" &
pid=$!
rows() { if [ -f "$tmp/int/energy.csv" ]; then wc -l < "$tmp/int/energy.csv"; else echo 0; fi; }
until [ "$(rows)" -gt 3 ] || ! kill -0 "$pid" 2> /dev/null; do sleep 0.05; done
kill -INT "$pid" 2> /dev/null || fail "the run ended before it could be interrupted"
set +e; wait "$pid"; code=$?; set -e
[ "$code" -eq 3 ] || fail "interrupted run exited $code, expected 3"
grep -q "interrupted at t = " "$tmp/int.log" || { cat "$tmp/int.log"; fail "no interruption message (did the run end first?)"; }
resume=$(grep -o -- "--resume [^ ]*" "$tmp/int.log" | cut -d' ' -f2)
"$polydem" run "$tmp/long.yaml" --out "$tmp/int" --resume "$resume" 2> /dev/null
cmp "$last_long" "$tmp/int/$(basename "$last_long")" || fail "run resumed after Ctrl-C differs from the uninterrupted one"

# Read the output with VTK itself.
/usr/bin/python3 "$here/check_output.py" "$tmp/full" 41 || fail "VTK output"
echo "cli: 1 passed, 0 failed"
