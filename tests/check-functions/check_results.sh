#!/usr/bin/env bash
# shellcheck disable=SC2016,SC2317  # the checks run through check(): bash -c with its own $1
# What the function checker gives a student and a course (docs/students.md): the
# chapter's verdict and its exit status (complete 0, incomplete 1, partial 3), what the
# student's code printed under the case it printed in, the command that runs a case
# alone (--function, --case) and the call to paste into a REPL, which does give what the
# checker reports; and --json, Gradescope's results.json, validated against
# gradescope-results.schema.json (Debian's python3-jsonschema; that part is skipped
# without it), never written over code. Skipped without node; the Python parts without
# python3.
# Usage: check_results.sh SOURCE_DIR WORK_DIR
set -euo pipefail
source_dir=$1 work=$2
rm -rf "$work"
mkdir -p "$work/py" "$work/js"
# shellcheck source=tests/check-functions/checks.sh
source "$(dirname "${BASH_SOURCE[0]}")/checks.sh"
if ! command -v node >/dev/null; then
  echo "SKIPPED: no node to run the checker (CI installs nodejs: scripts/setup)"
  exit 0
fi
checker=$source_dir/tools/check-functions/check-functions.js
reference=$source_dir/tools/check-functions/reference
schema=$source_dir/tests/check-functions/gradescope-results.schema.json
run() {  # the checker, its report in out.txt, its status in $status
  status=0
  node "$checker" "$@" >"$work/out.txt" 2>&1 || status=$?
  sed 's/^/    /' "$work/out.txt" | cut -c1-200
}
validator=0
/usr/bin/python3 -c 'import jsonschema' 2>/dev/null && validator=1
valid() {  # FILE: valid against the schema
  [ "$validator" -eq 1 ] || { echo "    (not validated: no python3-jsonschema; CI installs it)"; return 0; }
  /usr/bin/python3 - "$schema" "$1" <<'PY'
import json, sys
import jsonschema
jsonschema.validate(json.load(open(sys.argv[2])), json.load(open(sys.argv[1])))
PY
}
invalid() { ! valid "$1" 2>/dev/null; }
repl_call() {  # the lines to paste into a REPL, from the first failed case of out.txt
  awk '/^      in (python3|node), in your file.s folder:$/ { inside = 1; next }
    inside && !/^        / { exit } inside { sub(/^        /, ""); print }' "$work/out.txt"
}
field() {  # FILE EXPRESSION: a value of the results file, by a JavaScript expression on r
  node -e 'const r = JSON.parse(require("fs").readFileSync(process.argv[1], "utf8")); console.log(eval(process.argv[2]))' "$1" "$2"
}

echo "== the schema rejects what Gradescope's format does not allow"
printf '{"tests": [{"name": "x", "status": "passed"}]}\n' >"$work/no-score.json"
printf '{"score": 1, "tests": [{"name": "x", "status": "ok", "score": 1}]}\n' >"$work/bad-status.json"
printf '{"score": 1, "mine": 2}\n' >"$work/extra-field.json"
if [ $validator -eq 1 ]; then
  for bad in no-score bad-status extra-field; do
    check "the schema refuses $bad" invalid "$work/$bad.json"
  done
fi

languages=(js)
command -v python3 >/dev/null && languages=(py js)
for language in "${languages[@]}"; do
  if [ "$language" = py ]; then
    base=$reference/python/basic_rays.py file=$work/py/raytracer.py
    # y scaled by the width, and a print in CanvasToViewport
    sed -e 's|y \* Vh / Ch|y * Vh / Cw|' -e 's|^def CanvasToViewport(x, y):|&\n    print("canvas point", x, y)|' \
      -e '1a print("loading the chapter")' "$base" >"$file"
  else
    base=$reference/js/basic-rays.js file=$work/js/raytracer.js
    sed -e 's|y \* Vh / Ch|y * Vh / Cw|' -e 's|^function CanvasToViewport(x, y) {|&\n  console.log("canvas point", x, y);|' \
      -e '1a console.log("loading the chapter");' "$base" >"$file"
  fi
  echo "== $language: complete"
  run 02 "$base" --json "$work/complete.json"
  check "$language: a chapter that passes every case is complete, exit 0" test $status -eq 0
  check "$language: (its last line)" says "^chapter: complete \(20 cases: 20 passed\)$"
  check "$language: its results.json is valid" valid "$work/complete.json"
  check "$language: 20 tests, 20 points" test "$(field "$work/complete.json" 'r.tests.length + " " + r.score')" = "20 20"

  echo "== $language: incomplete, with what the code printed"
  run 02 "$file" --json "$work/incomplete.json"
  check "$language: a case failed: incomplete, exit 1" test $status -eq 1
  check "$language: (its last line)" says "^chapter: incomplete \(20 cases: 18 passed, 2 failed\)$"
  check "$language: what the code printed in that case, under it" says "^      \| canvas point 300 -200$"
  check "$language: only the failed cases' printing (cases 4 and 6)" bash -c '[ "$(grep -c "| canvas point" "$1")" -eq 2 ]' _ "$work/out.txt"
  check "$language: not what the file printed as it loaded" bash -c '! grep -q "| loading the chapter" "$1"' _ "$work/out.txt"
  check "$language: its results.json is valid" valid "$work/incomplete.json"
  check "$language: the failed test keeps what was printed, marked as the student's" \
    test "$(field "$work/incomplete.json" 'r.tests.filter((t) => t.status === "failed").map((t) => [t.extra_data.case, t.extra_data.status, t.extra_data.printed.trim(), t.extra_data.printed_by].join("|")).join(",")')" = \
    "4|fail|canvas point 300 -200|the student's code,6|fail|canvas point 300 -200|the student's code"
  check "$language: returned and expected, as data" \
    test "$(field "$work/incomplete.json" 'JSON.stringify(r.tests[3].extra_data.expected)')" = "[0.75,-0.5,1]"
  check "$language: the verdict in the file" test "$(field "$work/incomplete.json" 'r.extra_data.verdict')" = incomplete
  # The command printed under the case runs it alone, and says the same.
  alone=$(sed -n 's/^      alone: //p' "$work/out.txt" | head -1)
  (cd "$source_dir" && eval "$alone") >"$work/alone.txt" 2>&1 && status=0 || status=$?
  check "$language: the 'alone' command runs that case alone, exit 1" \
    bash -c '[ "$1" -eq 1 ] && grep -q "^CanvasToViewport, case 4: incomplete (1 case: 1 failed)$" "$2"' _ $status "$work/alone.txt"
  # The call to paste into a REPL gives what the checker reports.
  mapfile -t call < <(repl_call)
  if [ "$language" = py ]; then
    printf '%s\n' "${call[@]}" | sed '$ s/.*/print(list(&))/' | (cd "$work/py" && python3 -) >"$work/repl.txt" 2>&1 || true
    check "py: the REPL call gives the value the checker reported" grep -q "^\[0.75, -0.3333333333333333, 1\]$" "$work/repl.txt"
  else
    printf '%s\n' "${call[@]}" | (cd "$work/js" && node -i) >"$work/repl.txt" 2>&1 || true
    check "js: the REPL call gives the value the checker reported" grep -qE "0.75,( y:)? -0.3333333333333333,( z:)? 1" "$work/repl.txt"
  fi

  echo "== $language: partial"
  if [ "$language" = py ]; then
    printf 'Cw, Ch, Vw, Vh, d = 600, 600, 1, 1, 1\n\n\ndef CanvasToViewport(x, y):\n    return (x * Vw / Cw, y * Vh / Ch, d)\n' >"$work/py/one.py"
    one=$work/py/one.py
  else
    printf 'let Cw = 600, Ch = 600, Vw = 1, Vh = 1, d = 1;\nfunction CanvasToViewport(x, y) {\n  return [x * Vw / Cw, y * Vh / Ch, d];\n}\n' >"$work/js/one.js"
    one=$work/js/one.js
  fi
  run 02 "$one" --json "$work/partial.json"
  check "$language: one function written and passing: partial, exit 3" test $status -eq 3
  check "$language: (its last line)" says "^chapter: partial \(20 cases: 6 passed, 14 not written yet\)$"
  check "$language: its results.json is valid" valid "$work/partial.json"
  check "$language: the unwritten cases are 'not written'" \
    test "$(field "$work/partial.json" 'r.tests.filter((t) => t.extra_data.status === "not written").length')" = 14
done

if command -v python3 >/dev/null; then
  echo "== Listing 3-1: checked on its cases, the others not checked"
  python3 - "$reference/python/light.py" "$work/py/listing31.py" <<'PY'
import sys
text = open(sys.argv[1]).read()
start, end = text.index("# Listings 3-1 and 3-2"), text.index("# Listing 3-3")
listing = '''def ComputeLighting(P, N):
    i = 0.0
    for light in scene.lights:
        if light.type == "ambient":
            i += light.intensity
        else:
            L = subtract(light.position, P) if light.type == "point" else light.direction
            if dot(N, L) > 0:
                i += light.intensity * dot(N, L) / (length(N) * length(L))
    return i


'''
open(sys.argv[2], "w").write(text[:start] + listing)
PY
  run 03 "$work/py/listing31.py" --json "$work/listing31.json"
  check "a chapter 3 of Listing 3-1 alone is partial, exit 3" test $status -eq 3
  check "(3 cases not checked, TraceRay not written)" says "^chapter: partial \(24 cases: 15 passed, 6 not written yet, 3 not checked\)$"
  check "its results.json is valid" valid "$work/listing31.json"

  echo "== a file that cannot be checked, and where --json may not write"
  printf 'import numpy_that_is_not_there\n' >"$work/py/broken.py"
  run 02 "$work/py/broken.py" --json "$work/broken.json"
  check "a file that does not load: exit 1, one line" bash -c '[ "$1" -eq 1 ] && [ "$(wc -l <"$2")" -eq 1 ]' _ $status "$work/out.txt"
  check "the line names the Python that ran it and the module" says "the Python that ran it, .*python3.* \([0-9.]+\), has 'numpy_that_is_not_there'"
  check "its results.json is valid, with no test" valid "$work/broken.json"
  check "(and says why)" test "$(field "$work/broken.json" 'r.tests.length + " " + r.output.includes("does not load")')" = "0 true"
  cp "$work/py/one.py" "$work/py/keep.py"
  run 02 "$work/py/one.py" --json "$work/py/keep.py"
  check "--json onto a code file is refused, exit 2" test $status -eq 2
  check "(the file is untouched)" cmp -s "$work/py/one.py" "$work/py/keep.py"
  run 02 "$work/py/one.py" --json -
  check "--json - writes the results alone to standard output" bash -c 'node -e "JSON.parse(require(\"fs\").readFileSync(0, \"utf8\"))" <"$1"' _ "$work/out.txt"
  run 02 "$work/py/one.py" --function Nothing
  check "--function of no such function: exit 2, one line" bash -c '[ "$1" -eq 2 ] && [ "$(wc -l <"$2")" -eq 1 ]' _ $status "$work/out.txt"
  run 02 "$work/py/one.py" --case 3
  check "--case without --function: exit 2" test $status -eq 2
fi
echo "== the demos' names: the call to paste gives the records the checker gave"
# The checker's planes also answer to the demos' distance, its triangles to indexes, v0,
# v1 and v2; the call under a failed case gives each name the case's code read.
printf '%s\n' 'var SignedDistance = function (plane, vertex) {' \
  '  var n = plane.normal;' \
  '  return n[0] * vertex[0] + n[1] * vertex[1] + n[2] * vertex[2] - plane.distance;' \
  '};' 'module.exports = { SignedDistance };' >"$work/js/demos11.js"
run 11 "$work/js/demos11.js" --function SignedDistance --case 3
check "js: a plane's distance, D subtracted: returned -3" says "^      returned -3, expected -5"
repl_call | (cd "$work/js" && node -i) >"$work/repl.txt" 2>&1 || true
check "js: the REPL call gives the plane its distance, and -3" grep -qE "(^|> )-3$" "$work/repl.txt"
if command -v python3 >/dev/null; then
  sed 's/^        triangles.append(clipped(\[A, new_vertex(A, B), new_vertex(A, C)\]))$/        triangles.append(clipped([A, new_vertex(A, C), new_vertex(A, B)]))/' \
    "$source_dir/tests/check-functions/corpus/11_demos_translated.py" >"$work/py/demos11.py"
  run 11 "$work/py/demos11.py" --function ClipTriangle --case 3
  check "py: the demos' ClipTriangle, one triangle turned the other way: fails case 3" says "^ClipTriangle, case 3: incomplete"
  repl_call | sed '$ s/.*/print([t.indexes for t in &])/' | (cd "$work/py" && python3 -) >"$work/repl.txt" 2>&1 || true
  check "py: the REPL call gives the triangle its indexes, and an output list to fill" grep -qx "\[\[0, 3, 4\]\]" "$work/repl.txt"
fi
echo "== one number is said as one number"
mkdir -p "$work/js"
sed 's/^  return i;$/  return -1;/' "$reference/js/light.js" >"$work/js/light.js"
run 03 "$work/js/light.js" --function ComputeLighting
check "ComputeLighting returning -1: 'returned -1, expected 1', not '[-1]'" says "^      returned -1, expected 1 \(within 1e-9\)$"
[ $failed -eq 0 ] && echo "PASS: verdicts, exit statuses, printed output and results.json as documented"
exit $failed
