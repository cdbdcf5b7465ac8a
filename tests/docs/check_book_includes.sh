#!/usr/bin/env bash
# The chapters' book code stands on common/ alone: every file of a chapter but its
# program side (main.cpp, scenes.*, options.*) includes only the chapter's own book
# files, common/'s headers (cgfs/...), GLM and the standard library; never the program
# shell (program/...), the comparison (comparison/...) or the libraries behind them.
# Including one of the chapter's own book files only, this holds for everything a book
# file includes, however deep.
# Usage: check_book_includes.sh SOURCE_DIR
set -euo pipefail
cd "$1"
program_side() { [[ $1 =~ ^(main\.cpp|scenes\.(h|cpp)|options\.(h|cpp))$ ]]; }
failed=0
for file in chapters/[0-9][0-9]-*/*.h chapters/[0-9][0-9]-*/*.cpp; do
  folder=$(dirname "$file")
  program_side "$(basename "$file")" && continue
  while IFS=: read -r line include; do
    name=$(sed -E 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*[<"]([^>"]*)[>"].*/\1/' <<<"$include")
    if [[ $include =~ \" ]]; then
      if [[ $name == cgfs/* && ( -f common/include/$name || -f instrumentation/include/$name ) ]]; then
        continue
      fi
      if [[ $name != */* && -f $folder/$name ]] && ! program_side "$name"; then continue; fi
    else
      if [[ $name == glm/* || ($name != */* && $name != *.*) ]]; then continue; fi
    fi
    echo "FAIL: $file:$line includes $name: the book code includes only its chapter's" \
      "book files, common/ and instrumentation/ (cgfs/...), GLM and the standard library"
    failed=1
  done < <(grep -nE '^[[:space:]]*#[[:space:]]*include' "$file" || true)
done
[ "$failed" = 0 ] && echo "every chapter's book code includes only common/, GLM and the standard library"
exit "$failed"
