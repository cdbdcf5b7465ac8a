#!/usr/bin/env bash
# The chapters' book code counts work only through the tally (cgfs/tally.h), one line
# per event: no book header (a chapter's files but its program side, main.cpp, scenes.*,
# options.*, and its cost views' drivers, cost.*) declares a pointer to counts, an
# out-parameter of counts, a counting setter (Count...) or a counting policy (a template
# parameter Count, or a struct Tests passed by pointer). See the README's layout table.
# Usage: check_book_counting.sh SOURCE_DIR
set -euo pipefail
cd "$1"
not_book() { [[ $1 =~ ^(main\.cpp|scenes\.(h|cpp)|options\.(h|cpp)|cost\.(h|cpp))$ ]]; }
pattern='\b(long|std::vector<long>|std::atomic<long>)[[:space:]]*\*|std::vector<long>[[:space:]]*&[[:space:]]*[A-Za-z_]|\bCount[A-Z][A-Za-z]*[[:space:]]*\(|typename Count\b|\bTests[[:space:]]*\*'
comment='^[[:space:]]*//'
failed=0
# One grep over every header, each line it finds read here without a process of its own.
while IFS=: read -r file line text; do
  not_book "${file##*/}" && continue
  [[ $text =~ $comment ]] && continue
  echo "FAIL: $file:$line:$text: book code counts work through the tally (cgfs/tally.h, one" \
    "line at the event), never through pointers, out-parameters, setters or policies"
  failed=1
done < <(grep -nHE "$pattern" chapters/[0-9][0-9]-*/*.h || true)
[ "$failed" = 0 ] && echo "no book header counts work but through the tally"
exit "$failed"
