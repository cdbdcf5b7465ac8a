#!/usr/bin/env bash
# Every shell script of the project (scripts/, tests/, .ci/run) is clean when
# ShellCheck reads it at the severity "warning" (its infos are style, and some are
# meant: a single-quoted $1 for an inner shell). Skipped without shellcheck (CI installs it:
# scripts/setup). Usage: check_shell_scripts.sh SOURCE_DIR
set -euo pipefail
cd "$1"
if ! command -v shellcheck >/dev/null; then
  echo "SKIPPED: no shellcheck (CI installs it: scripts/setup)"
  exit 0
fi
files=()
while IFS= read -r file; do
  head -1 "$file" | grep -qE '^#!.*\b(ba)?sh\b' || [[ $file == *.sh ]] || continue
  files+=("$file")
done < <(git ls-files 'scripts/*' '*.sh' .ci/run 2>/dev/null || find scripts tests .ci -type f)
# (-x: the files a script sources are read with it; one run for all: each warning names
# its file)
if shellcheck -x -S warning "${files[@]}"; then
  echo "PASS: ${#files[@]} shell scripts clean under shellcheck"
else
  echo "FAIL: shellcheck's warnings above"
  exit 1
fi
