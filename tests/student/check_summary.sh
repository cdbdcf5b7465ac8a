#!/usr/bin/env bash
# scripts/summarise-student-tests.awk, the summary scripts/test-student prints, on a
# made-up ctest run: a book function's tests under its name, golden images together,
# and every other test on a line of its own, under its own name, passed or failed, a
# name longer than the names' column above its verdict, which stays in its column.
# Usage: check_summary.sh SOURCE_DIR WORK_DIR
set -euo pipefail
source_dir=$1 work=$2
rm -rf "$work"
mkdir -p "$work"
echo "Start testing" >"$work/LastTest.log"  # as ctest writes it: never empty
cat >"$work/console.txt" <<'LINES'
1/5 Test #2: 03-light: ComputeLighting: the cases of 03-light.json .........   Passed    0.01 sec
2/5 Test #3: 03-light: the green highlight goes above 255 before it is clamped ...   Passed    0.01 sec
3/5 Test #4: 03-light: fig-3-7-diffuse matches its golden image ...***Failed    0.10 sec
4/5 Test #5: 03-light: Listing 3-1 lights a matte sphere .................***Failed    0.01 sec
5/5 Test #6: 03-light: RenderScene paints every pixel of the canvas ........   Passed    0.01 sec
LINES
awk -f "$source_dir/scripts/summarise-student-tests.awk" "$work/LastTest.log" "$work/console.txt" >"$work/out.txt"
cat "$work/out.txt"
failed=0
want() { grep -qxF -- "$1" "$work/out.txt" || { echo "FAIL: no line '$1'"; failed=1; }; }
want "03-light: 3 passed, 2 failed, 0 not written yet"
want "  ComputeLighting        passed (1 test)"
want "  the green highlight goes above 255 before it is clamped"
want "                         passed (1 test)"
want "  golden images          FAILED 1 of 1 tests"
want "  Listing 3-1 lights a matte sphere"
want "                         FAILED 1 of 1 tests"
want "  RenderScene            passed (1 test)"
[ $failed -eq 0 ] && echo "PASS: the summary names every test"
exit $failed
