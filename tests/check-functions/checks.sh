# Sourced by the function checker's test scripts: check WHAT COMMAND... prints "ok: WHAT"
# or "FAIL: WHAT" (and sets failed=1) by the command's status; says PATTERN: whether
# the last run's output, $work/out.txt, has a line matching PATTERN (grep -E);
# promised CASES LIMIT: the seconds a run may take (below).
# shellcheck shell=bash
# shellcheck disable=SC2034,SC2154 # failed is read, and work set, by the script that sources this
failed=0
check() {
  local what=$1
  shift
  if "$@"; then echo "ok: $what"; else echo "FAIL: $what"; failed=1; fi
}
says() { grep -qE -- "$1" "$work/out.txt"; }

# The most a run of CASES cases with --time-limit LIMIT may take by the checker's own
# promise (CASES x LIMIT + 60 s to load; it stops there and says so: check_hostile.sh's
# "a run bounded by its cases"), and 15 s more for starting the sandbox and an
# interpreter (under a second quiet; a few seconds beside four CPU-bound processes,
# when runs that take 3 s quiet took up to 26 s). A run within it was cut where the
# checker promises, whatever the machine's load; a hang that is not cut runs on to
# ctest's timeout. That each case was cut at its own limit is the report's to say.
promised() {
  awk -v cases="$1" -v limit="$2" 'BEGIN { bound = cases * limit + 60 + 15
    printf "%d", bound == int(bound) ? bound : int(bound) + 1 }'
}
