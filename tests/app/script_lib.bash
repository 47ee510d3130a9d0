# Shared by the command-line tests (tests/app/*.sh): `source "$(dirname "$0")/script_lib.bash" "$1"`.
# Sets polydem (the binary under test), here (this folder), tmp (removed on exit), and
# fail / expect_exit / sigterm_after_rows. Not a test itself: CMake registers *.sh only.
polydem=$1
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
# expect_exit CODE PATTERN COMMAND...: exit code and a pattern of stdout/stderr; a script that
# sets expect_timeout (s) stops a hang there.
expect_exit() {
  local code=$1 pattern=$2; shift 2
  set +e; ${expect_timeout:+timeout "$expect_timeout"} "$@" > "$tmp/out" 2> "$tmp/err"; local got=$?; set -e
  [ "$got" -eq "$code" ] || { cat "$tmp/err"; fail "$* exited $got, expected $code"; }
  grep -q -- "$pattern" "$tmp/out" "$tmp/err" || { cat "$tmp/out" "$tmp/err"; fail "$*: no '$pattern' in the output"; }
}
# sigterm_after_rows PID DIR LOG: SIGTERM to run PID (a child of this shell, so not in a $(...))
# once DIR/energy.csv has 4 rows; expects exit 3 and sets `resume` to the checkpoint LOG names.
sigterm_after_rows() {
  local pid=$1 dir=$2 log=$3 code
  rows() { if [ -f "$dir/energy.csv" ]; then wc -l < "$dir/energy.csv"; else echo 0; fi; }
  until [ "$(rows)" -gt 3 ] || ! kill -0 "$pid" 2> /dev/null; do sleep 0.05; done
  kill -TERM "$pid" 2> /dev/null || fail "the run ended before it could be stopped"
  set +e; wait "$pid"; code=$?; set -e
  [ "$code" -eq 3 ] || { cat "$log"; fail "SIGTERM: exit code $code, expected 3"; }
  resume=$(grep -o -- "--resume [^ ]*" "$log" | cut -d' ' -f2)
  [ -f "$resume" ] || { cat "$log"; fail "no checkpoint after SIGTERM"; }
}
