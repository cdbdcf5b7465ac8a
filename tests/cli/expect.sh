# The command-line checks' one helper, sourced by them: set `work` (a scratch folder)
# and `failures` (0) first.
#
# expect STATUS DESCRIPTION COMMAND...: the command exits with STATUS; an error
# (status 2) is exactly one line on standard error.
# shellcheck shell=bash disable=SC2154 # work is set by the script that sources this
expect() {
  local want=$1 what=$2
  shift 2
  "$@" >"$work/stdout" 2>"$work/stderr"
  local got=$?
  if [ "$got" -ne "$want" ]; then
    echo "FAIL: $what: exit status $got, expected $want"
    cat "$work/stderr"
    failures=$((failures + 1))
  elif [ "$want" -eq 2 ] && [ "$(wc -l <"$work/stderr")" -ne 1 ]; then
    echo "FAIL: $what: the error is not one line:"
    cat "$work/stderr"
    failures=$((failures + 1))
  else
    echo "ok: $what (exit $want)$( [ "$want" -eq 2 ] && echo ": $(cat "$work/stderr")")"
  fi
}
