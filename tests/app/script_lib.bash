# Shared by the command-line tests (tests/app/*.sh): `source "$(dirname "$0")/script_lib.bash" "$1"`.
# Sets polydem (the binary under test), here (this folder), tmp (removed on exit), and
# fail / expect_exit. Not a test itself: CMake registers *.sh only.
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
