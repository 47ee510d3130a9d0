#!/usr/bin/env bash
# Numbers a run cannot honour are refused before the first step, with exit code 1 and one line
# naming the file, line and key (or the option): schedules and dt against the duration and the
# step count's range, --until, stiffness, driver speed, grid size, names, threads, --out. A
# hang would stop the test at its `timeout` (10 s; each case ends in well under a second).
# usage: limits.sh PATH/TO/polydem
set -euo pipefail
source "$(dirname "$0")/script_lib.bash" "$1"
expect_timeout=10  # s: each case ends in well under a second; a hang fails here
scene() {  # scene NAME SED-EXPRESSION: drop.yaml changed by the expression
  sed -e "s|\.\./\.\./shapes|$here/../../shapes|" -e "$2" "$here/drop.yaml" > "$tmp/$1.yaml"
}

# Schedules below the round-off of t used to loop for ever.
scene ckpt 's|checkpoint_every: "20 ms"|checkpoint_every: 1e-300|'
expect_exit 1 "ckpt.yaml:33: key 'checkpoint_every': 1e-300 s is below 0.001 x the time step" "$polydem" run "$tmp/ckpt.yaml" --out "$tmp/o"
expect_exit 1 "ckpt.yaml:33: key 'checkpoint_every'" "$polydem" check "$tmp/ckpt.yaml"
scene csv 's|csv_every: "1 ms"|csv_every: 1e-300|'
expect_exit 1 "csv.yaml:32: key 'csv_every'" "$polydem" run "$tmp/csv.yaml" --out "$tmp/o"
scene dt 's|dt: auto|dt: 1e300|'
expect_exit 1 "dt.yaml:4: key 'dt': the step 1e300 is longer than the duration" "$polydem" run "$tmp/dt.yaml" --out "$tmp/o" --until 0.0004
scene dt2 's|dt: auto|dt: 2147483648|'
expect_exit 1 "dt2.yaml:4: key 'dt'" "$polydem" run "$tmp/dt2.yaml" --out "$tmp/o" --until 0.0004
# A stiffness whose step overflows the step count used to run 0 steps and exit 0.
scene kn 's|kn: 1.0e5|kn: 1e300|'
expect_exit 1 "kn.yaml:27: key 'kn': kn = 1e+300 N/m sets dt: auto to" "$polydem" run "$tmp/kn.yaml" --out "$tmp/o"
expect_exit 1 "beyond the 9.01e+15 steps" "$polydem" check "$tmp/kn.yaml"
expect_exit 1 "--until: expected a time" "$polydem" run "$here/drop.yaml" --out "$tmp/o" --until nan
expect_exit 1 "--until: expected a time" "$polydem" run "$here/drop.yaml" --out "$tmp/o" --until inf
expect_exit 1 "--until 1e+300 s asks for" "$polydem" run "$here/drop.yaml" --out "$tmp/o" --until 1e300
# A driver turning 1e294 rad a step used to write driver_work = nan and exit 0.
scene omega 's|- wall: {name: floor, point: \[0, 0, 0\], normal: \[0, 0, 1\]}|- cylinder: {name: drum, center: [0, 0, 0], axis: [0, 1, 0], radius: 0.3, length: 0.1, motion: {rotate: {axis: [0, 1, 0], center: [0, 0, 0], omega: 1e300}}}|'
expect_exit 1 "omega.yaml:21: key 'omega': driver 'drum' turns" "$polydem" run "$tmp/omega.yaml" --out "$tmp/o"
# Gravity of 1e300 m/s^2 turned the state non-finite in two steps (exit 2); a centrifuge's
# 1,000 g is a scene, not a mistake.
scene gravity 's|gravity: \[0, 0, -9.807\]|gravity: [0, 0, -1e300]|'
expect_exit 1 "gravity.yaml:26: key 'gravity': 1e+300 m/s^2 moves a body" "$polydem" run "$tmp/gravity.yaml" --out "$tmp/o"
scene centrifuge 's|gravity: \[0, 0, -9.807\]|gravity: [0, 0, -9807]|'
"$polydem" check "$tmp/centrifuge.yaml" > /dev/null || fail "gravity of 1,000 g refused"
# Messages with the file and line.
scene kt 's|kt: 1.0e5|kt: 0|'
expect_exit 1 "kt.yaml:28: key 'kt': mu > 0 needs kt > 0" "$polydem" check "$tmp/kt.yaml"
scene name 's|name: floor|name: "../../escaped"|'
expect_exit 1 "name.yaml:21: key 'name': '../../escaped' must be letters" "$polydem" check "$tmp/name.yaml"
cat > "$tmp/grid.yaml" << 'YAML'
simulation: {duration: 0.01, dt: 1e-4}
forces:
  - fluid_field: {grid: {min: [0, 0, 0], max: [1, 1, 1], cells: [100000, 100000, 100000]}, velocity: [0, 0, 0], rho: 1000, nu: 1e-6}
YAML
expect_exit 1 "grid.yaml:3: key 'cells': 100000 x 100000 x 100000 cells is more than the limit" "$polydem" check "$tmp/grid.yaml"
sed -e 's|dt: 1e-4||' -e 's|100000, 100000, 100000|2, 2, 2|' "$tmp/grid.yaml" > "$tmp/noauto.yaml"
expect_exit 1 "noauto.yaml:1: key 'dt': 'auto' needs a contact law" "$polydem" check "$tmp/noauto.yaml"
# Command line.
expect_exit 1 "output folder '$here/drop.yaml' is a file" "$polydem" run "$here/drop.yaml" --out "$here/drop.yaml"
expect_exit 1 "--threads: expected a whole number >= 1, got '2.5'" "$polydem" run "$here/drop.yaml" --out "$tmp/o" --threads 2.5
expect_exit 0 "warning: --threads: 1000 threads on" "$polydem" run "$here/drop.yaml" --out "$tmp/o" --threads 1000 --until 0.0002
expect_exit 1 "--force goes with --resume" "$polydem" run "$here/drop.yaml" --out "$tmp/o" --force
# Warnings where a user may mean it.
scene every 's|csv_every: "1 ms"|csv_every: "1 us"|'
expect_exit 0 "warning: .*every.yaml:32: key 'csv_every': 1e-06 s is shorter than the time step" "$polydem" run "$tmp/every.yaml" --out "$tmp/o" --until 0.0001
scene skin 's|seed: 3|seed: 3\n  skin: 2|'
expect_exit 0 "warning: .*skin.yaml:6: key 'skin': 2 m is .* x the largest body radius" "$polydem" check "$tmp/skin.yaml"
expect_exit 0 "warning: .*key 'vtk_every': 0.01 s is longer than the run" "$polydem" run "$here/drop.yaml" --out "$tmp/o" --until 0.001
echo "limits: 1 passed, 0 failed"
