#!/usr/bin/env bash
# The HTML report of `cgfs-compare --report`, loaded in a real browser (headless
# Chromium): a student folder with one right figure, one wrong, one moved one row
# down and one missing (its image misnamed). Checks the verdicts printed, that each
# failed figure links its chapter's function cases (tests/cases), and in
# the browser that every image shows, that the counts at the top match the rows,
# that a click enlarges an image and another shrinks it, and that no Markdown file is
# linked. One page load does all (a screenshot to look at: chromium --headless
# --screenshot on WORK_DIR/mine/report.html). Without Chromium the browser part is skipped.
# Usage: check_report_in_browser.sh CHAPTER_02_PROGRAM CGFS_COMPARE WORK_DIR
set -euo pipefail
program=$1 compare=$2 work=$3
rm -rf "$work"
mkdir -p "$work/mine/02-basic-rays" "$work/mine/03-light" "$work/ours"
"$program" --output "$work/ours" --format ppm >/dev/null
cp "$work/ours/fig-2-11.ppm" "$work/mine/02-basic-rays/"                        # right
{ printf 'P6\n600 600\n255\n'; head -c 1800 /dev/zero | tr '\0' '\377'
  tail -c +16 "$work/ours/fig-2-11-with-ground.ppm" | head -c $((599 * 1800)); } \
  >"$work/mine/02-basic-rays/fig-2-11-with-ground.ppm"                           # one row down
cp "$work/ours/fig-2-11.ppm" "$work/mine/03-light/fig-3-7-diffuse.ppm"            # wrong
cp "$work/ours/fig-2-11.ppm" "$work/mine/03-light/fig-3-16.ppm"                  # misnamed, so
                                                                                 # fig-3-16: missing
status=0
"$compare" --report "$work/mine" >"$work/out.txt" || status=$?
cat "$work/out.txt"
failed=0
want() { grep -qF "$1" "$work/out.txt" || { echo "FAIL: no line '$1'"; failed=1; }; }
[ $status -eq 1 ] || { echo "FAIL: exit status $status, expected 1"; failed=1; }
want "02-basic-rays/fig-2-11: PASS"
want "02-basic-rays/fig-2-11-with-ground: FAIL (your image is ours moved one row down"
want "03-light/fig-3-7-diffuse: FAIL"
want "03-light/fig-3-16-specular: missing"
want "03-light/fig-3-16.ppm: not one of our figures, not compared (did you mean fig-3-16-specular?)"
# A failed figure of a chapter with function cases points to them, and to the checkers.
cases_links=$(grep -o '<p class="cases">Its functions one at a time, on the cases of <a href="file://[^"]*/tests/cases/0[23]-[a-z-]*\.json">' \
  "$work/mine/report.html" | wc -l)
[ "$cases_links" -eq 2 ] || { echo "FAIL: $cases_links failed figures link their chapter's function cases, not 2"; failed=1; }
# Each figure names its chapter's README by its place in the repository, not by a path of
# this machine's.
readmes=$(grep -o '<code>chapters/0[23]-[a-z-]*/README.md</code> in this repository' "$work/mine/report.html" | wc -l)
[ "$readmes" -eq 4 ] || { echo "FAIL: $readmes figures name their chapter's README, not 4"; failed=1; }

browser=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$browser" ]; then
  echo "SKIPPED: no chromium to load the page in (CI installs it: scripts/setup)"
  exit $failed
fi
page="file://$work/mine/report.html"
flags=(--headless --no-sandbox --disable-gpu --hide-scrollbars)
# Opened as #click-test, the page also clicks a failed figure's 600-pixel image twice
# (full size, then back) and adds the widths it saw to the line it fills in.
dom=$(timeout 120 "$browser" "${flags[@]}" --dump-dom "$page#click-test" 2>/dev/null)
check=$(grep -o '<p id="check">[^<]*' <<<"$dom" | sed 's/.*>//; s/; click: .*//')
echo "the browser counted: $check"
expected="images shown: 10 of 10; rows passed: 1, failed: 2, missing: 1"
[ "$check" = "$expected" ] || { echo "FAIL: expected '$expected'"; failed=1; }
clicked=$(grep -o '<p id="check">[^<]*' <<<"$dom" | sed 's/.*; click: //')
echo "widths of a clicked image: $clicked"
[ "$clicked" = "300, 600, 300 px" ] || { echo "FAIL: expected '300, 600, 300 px'"; failed=1; }
if grep -q 'href="[^"]*\.md"' <<<"$dom"; then
  echo "FAIL: the page links a Markdown file, which a browser shows as raw text"; failed=1
fi
summary=$(grep -o '<p id="summary">.*</p>' <<<"$dom" | sed 's/<[^>]*>//g')
echo "the page says: $summary"
[ "$summary" = "1 passed, 2 failed, 1 missing" ] || { echo "FAIL: wrong summary"; failed=1; }
[ $failed -eq 0 ] && echo "PASS: the report shows every figure as it should"
exit $failed
