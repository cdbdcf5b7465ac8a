#!/usr/bin/env bash
# Every shell script of the project (scripts/, tests/, .ci/run) is clean under
# shellcheck at the severity "warning" (its infos are style, and some are meant: a
# single-quoted $1 for an inner shell). Skipped without shellcheck (CI installs it:
# scripts/setup). Usage: check_shell_scripts.sh SOURCE_DIR
set -euo pipefail
cd "$1"
if ! command -v shellcheck >/dev/null; then
  echo "SKIPPED: no shellcheck (CI installs it: scripts/setup)"
  exit 0
fi
failed=0 count=0
while IFS= read -r file; do
  head -1 "$file" | grep -qE '^#!.*\b(ba)?sh\b' || [[ $file == *.sh ]] || continue
  count=$((count + 1))
  # (-x: the files a script sources are read with it)
  if ! shellcheck -x -S warning "$file"; then
    echo "FAIL: $file"
    failed=1
  fi
done < <(git ls-files 'scripts/*' '*.sh' .ci/run 2>/dev/null || find scripts tests .ci -type f)
[ $failed -eq 0 ] && echo "PASS: $count shell scripts clean under shellcheck"
exit $failed
