#!/usr/bin/env bash
# `polydem run` starts again with GOMP_SPINCOUNT=1000 when the environment chooses no OpenMP wait
# (libgomp reads it once, at load), and keeps a wait the user chose. The second image keeps the
# arguments, the exit code and the process id (a signal to the first pid stops the run).
# usage: short_spin.sh PATH/TO/polydem
set -euo pipefail
source "$(dirname "$0")/script_lib.bash" "$1"
sed -e "s|\.\./\.\./shapes|$here/../../shapes|" "$here/drop.yaml" > "$tmp/drop.yaml"
first_line() { head -1 "$tmp/err"; }
bare() { env -u OMP_WAIT_POLICY -u GOMP_SPINCOUNT "$@"; }  # [NAME=VALUE] COMMAND: ctest sets a passive wait

bare "$polydem" run "$tmp/drop.yaml" --out "$tmp/o" --until 2e-3 --threads 2 2> "$tmp/err"
first_line | grep -q "2 threads, GOMP_SPINCOUNT=1000, output" || fail "no short spin: $(first_line)"
bare OMP_WAIT_POLICY=passive "$polydem" run "$tmp/drop.yaml" --out "$tmp/o" --until 2e-3 --threads 2 2> "$tmp/err"
first_line | grep -q "2 threads, OMP_WAIT_POLICY=passive, output" || fail "the user's wait lost: $(first_line)"
bare GOMP_SPINCOUNT=20000 "$polydem" run "$tmp/drop.yaml" --out "$tmp/o" --until 2e-3 --threads 2 2> "$tmp/err"
first_line | grep -q "2 threads, GOMP_SPINCOUNT=20000, output" || fail "the user's spin lost: $(first_line)"

# Threads the user binds: no second image, which would inherit the first thread's one core.
bare OMP_PROC_BIND=true "$polydem" run "$tmp/drop.yaml" --out "$tmp/o" --until 2e-3 --threads 2 2> "$tmp/err"
first_line | grep -q "2 threads, OMP_PROC_BIND=true, output" || fail "bound threads started again: $(first_line)"
if [ "$(nproc)" -ge 2 ] && grep -q "on 1 cores" "$tmp/err"; then fail "bound threads on one core: $(cat "$tmp/err")"; fi

# Arguments and exit code through the second image.
expect_exit 1 "--until: expected a time" bare "$polydem" run "$tmp/drop.yaml" --out "$tmp/o" --until nan

# SIGTERM to the pid the shell started: exit 3 and a checkpoint, as without the second image.
sed "s/duration: \"40 ms\"/duration: \"400 ms\"/" "$tmp/drop.yaml" > "$tmp/long.yaml"
env -u OMP_WAIT_POLICY -u GOMP_SPINCOUNT "$polydem" run "$tmp/long.yaml" --out "$tmp/term" --threads 2 \
  2> "$tmp/term.log" &  # not through `bare`: its subshell would take the signal
sigterm_after_rows $! "$tmp/term" "$tmp/term.log"
echo "short_spin: ok"
