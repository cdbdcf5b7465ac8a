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
# What an include names: its path between the quotes or the angle brackets.
include_pattern='^[[:space:]]*#[[:space:]]*include[[:space:]]*[<"]([^>"]*)[>"]'
failed=0
# One grep over every file, each line it finds read without starting a process (on a
# machine slow to start them, a process per line took most of a minute).
while IFS=: read -r file line include; do
  folder=${file%/*}
  program_side "${file##*/}" && continue
  name=$include
  [[ $include =~ $include_pattern ]] && name=${BASH_REMATCH[1]}
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
done < <(grep -nHE '^[[:space:]]*#[[:space:]]*include' chapters/[0-9][0-9]-*/*.h \
  chapters/[0-9][0-9]-*/*.cpp || true)
[ "$failed" = 0 ] && echo "every chapter's book code includes only common/, GLM and the standard library"
exit "$failed"
