#!/usr/bin/env bash
# Each chapter README's "Changed headers" line (docs/students.md, "Moving on to the
# next chapter") names exactly the headers that differ from the previous chapter's:
# changed, new and gone. A chapter that starts afresh ("Headers, for a student: ...")
# names all of its own as new, and a bonus chapter built on an earlier chapter than the
# folder before it ("for a student's copy of chapter 05") is compared with that one.
# Usage: check_changed_headers.sh SOURCE_DIR
set -euo pipefail
cd "$1"
names() { grep -o '`[^`]*\.h`' | tr -d '`' | sort | paste -sd' ' || true; }
failed=0
previous=""
for folder in chapters/[0-9][0-9]-*/; do
  chapter=${folder%/}
  chapter=${chapter##*/}
  if [ -z "$previous" ]; then previous=$chapter; continue; fi
  paragraph=$(awk '/^(Changed headers|Headers, for a student)/ { p = 1 } p && /^$/ { exit } p' \
    "chapters/$chapter/README.md" | tr '\n' ' ')
  last=$chapter
  # A bonus chapter built on an earlier one than the folder before it names its base.
  if [[ $paragraph =~ copy\ of\ chapter\ ([0-9][0-9]) ]]; then
    base=(chapters/"${BASH_REMATCH[1]}"-*)
    previous=${base[0]##*/}
  fi
  changed="" new="" gone=""
  for header in chapters/"$chapter"/*.h; do
    name=${header##*/}
    if [ ! -f "chapters/$previous/$name" ]; then new="$new $name"
    elif ! cmp -s "chapters/$previous/$name" "$header"; then changed="$changed $name"; fi
  done
  for header in chapters/"$previous"/*.h; do
    [ -f "chapters/$chapter/${header##*/}" ] || gone="$gone ${header##*/}"
  done
  if [ -z "$paragraph" ]; then
    echo "FAIL: chapters/$chapter/README.md has no \"Changed headers\" paragraph"; failed=1
    previous=$last; continue
  fi
  if [[ $paragraph == Headers,* ]]; then  # afresh: every header is new
    want="|$(printf '%s\n' $changed $new | sort | paste -sd' ')|"
  else
    want="$(printf '%s\n' $changed | sort | paste -sd' ')|$(printf '%s\n' $new | sort | paste -sd' ')|$(printf '%s\n' $gone | sort | paste -sd' ')"
  fi
  listed_changed=$(sed 's/; new:.*//; s/; gone:.*//; s/.*: //' <<<"$paragraph" | names)
  listed_new=$(grep -o '; new:[^;]*' <<<"$paragraph" | names || true)
  listed_gone=$(grep -o '; gone:[^;]*' <<<"$paragraph" | names || true)
  [[ $paragraph == Headers,* ]] && listed_new=$(sed 's/.*new://' <<<"$paragraph" | names) && listed_changed=""
  got="$listed_changed|$listed_new|$listed_gone"
  if [ "$got" != "$want" ]; then
    echo "FAIL: chapters/$chapter/README.md lists (changed|new|gone) '$got', the folders say '$want'"
    failed=1
  else
    echo "ok: $chapter: $got"
  fi
  previous=$last
done
exit $failed
