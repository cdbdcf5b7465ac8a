# Sourced by the function checker's test scripts: check WHAT COMMAND... prints "ok: WHAT"
# or "FAIL: WHAT" (and sets failed=1) by the command's status; says PATTERN: whether
# the last run's output, $work/out.txt, has a line matching PATTERN (grep -E).
# shellcheck shell=bash
failed=0
check() {
  local what=$1
  shift
  if "$@"; then echo "ok: $what"; else echo "FAIL: $what"; failed=1; fi
}
says() { grep -qE -- "$1" "$work/out.txt"; }
