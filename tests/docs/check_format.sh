#!/usr/bin/env bash
# The project's code is as its formatter writes it: C++ as clang-format writes it
# (.clang-format), Python as black writes it (pyproject.toml), JavaScript as prettier
# writes it (.prettierrc.json; the version pinned in tools/format/package-lock.json,
# which scripts/setup installs into tools/format/node_modules), its functions, methods
# and variables camelCase and its classes PascalCase. The students' chapters
# of the checkers' tests keep their authors' styles (.prettierignore, pyproject.toml).
# Skipped, with the reason, where the formatter is not installed (CI installs each:
# scripts/setup). To format: the command each failure prints.
# Usage: check_format.sh SOURCE_DIR cpp|python|javascript
set -euo pipefail
cd "$1"
# One JavaScript dialect: functions, methods and variables are camelCase, classes
# PascalCase (the pages', the checkers' and their tests' alike; the students' code of
# the checkers' tests, forgers included, uses the book's names).
camel_case() {
  local js
  mapfile -t js < <(git ls-files '*.js' '*.mjs' ':!tests/check-functions/corpus' \
    ':!tests/check-functions/students' ':!tests/check-functions/forgers' \
    ':!tools/check-functions/reference/js')
  if grep -nE '^\s*(export )?(async )?function\*? [A-Z]|^\s*(export )?(const|let) [A-Z][a-z][A-Za-z0-9]* = (async )?(\(|[a-z_]+ =>)|^\s+(static |async |get |set )*[A-Z][A-Za-z0-9]*\([^)]*\) \{$' "${js[@]}"; then
    echo "FAIL: javascript: the functions, methods or variables above are not camelCase"
    exit 1
  fi
}

case $2 in
  cpp)
    command -v clang-format >/dev/null || { echo "SKIPPED: no clang-format (CI installs it: scripts/setup)"; exit 0; }
    mapfile -t files < <(git ls-files '*.cpp' '*.h')
    fix="clang-format -i \$(git ls-files '*.cpp' '*.h')"
    check() { clang-format --dry-run -Werror "${files[@]}"; }
    ;;
  python)
    command -v black >/dev/null || { echo "SKIPPED: no black (CI installs it: scripts/setup)"; exit 0; }
    fix="black ."
    check() { black --check --quiet .; }
    ;;
  javascript)
    prettier=tools/format/node_modules/.bin/prettier
    [ -x "$prettier" ] || { echo "SKIPPED: no $prettier (scripts/setup installs it with npm ci in tools/format)"; exit 0; }
    fix="$prettier --write '**/*.{js,mjs}'"
    check() { "$prettier" --check --log-level warn '**/*.{js,mjs}' && camel_case; }
    ;;
  *)
    echo "usage: check_format.sh SOURCE_DIR cpp|python|javascript" >&2
    exit 2
    ;;
esac
if check; then
  echo "PASS: $2 as its formatter writes it"
else
  echo "FAIL: $2 not as its formatter writes it (the files above); to format: $fix"
  exit 1
fi
