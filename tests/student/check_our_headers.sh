#!/usr/bin/env bash
# scripts/check-student-headers on our own chapters, as if they were a student's:
# every book function of every chapter header is found with its own signature (no
# false alarm from the declaration reader, scripts/book-declarations.awk), and the
# reader finds the functions at all (a count per chapter).
# Usage: check_our_headers.sh SOURCE_DIR WORK_DIR
set -euo pipefail
source_dir=$1 work=$2
cd "$source_dir"
rm -rf "$work"
cmake -S . -B "$work" -G Ninja -DCGFS_STUDENT_DIR="$source_dir/chapters" >"$work.configure.log" 2>&1 \
  || { cat "$work.configure.log"; exit 1; }
chapters=$(cd chapters && ls -d [0-9][0-9]-*)
failed=0
for chapter in $chapters; do
  count=$(cat chapters/"$chapter"/*.h | awk -f scripts/book-declarations.awk | wc -l)
  echo "$chapter: $count book functions declared"
  [ "$count" -gt 0 ] || { echo "FAIL: none found in $chapter"; failed=1; }
done
# Every chapter's probes in one go: silent, exit status 0.
if ! output=$(scripts/check-student-headers "$source_dir/chapters" "$work" $chapters 2>&1) ||
   [ -n "$output" ]; then
  echo "$output"
  echo "FAIL: our own headers are reported unlike ours"
  failed=1
fi
[ $failed -eq 0 ] && echo "PASS: every chapter's headers match themselves"
exit $failed
