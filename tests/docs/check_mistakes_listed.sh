#!/usr/bin/env bash
# Each chapter README's "## Mistakes the tests catch" section is its catalogue
# (tests/mistakes/CHAPTER.txt) as `scripts/mistakes --list` prints it, and a chapter
# without a catalogue has no such section.
# Usage: check_mistakes_listed.sh SOURCE_DIR
set -euo pipefail
cd "$1"
failed=0
for readme in chapters/*/README.md; do
  chapter=$(basename "$(dirname "$readme")")
  section=$(awk '/^## Mistakes the tests catch$/ { inside = 1 } inside && /^## / && !/^## Mistakes/ { exit }
    inside { print }' "$readme")
  if [ -f "tests/mistakes/$chapter.txt" ]; then
    if [ "$section" = "$(scripts/mistakes --list "${chapter%%-*}")" ]; then
      echo "ok: $chapter lists its catalogue"
    else
      echo "FAIL: $readme's \"Mistakes the tests catch\" is not scripts/mistakes --list ${chapter%%-*}:"
      diff <(echo "$section") <(scripts/mistakes --list "${chapter%%-*}") || true
      failed=1
    fi
  elif [ -n "$section" ]; then
    echo "FAIL: $readme lists mistakes, and $chapter has no catalogue (tests/mistakes/)"
    failed=1
  fi
done
[ $failed -eq 0 ] && echo "PASS: the READMEs list the catalogues of mistakes"
exit $failed
