#!/usr/bin/env bash
# The runners for other languages (tools/check-functions), as a student uses them:
# our Python and JavaScript references of each chapter pass every case; a copy of a
# reference with mistakes gets, per function, the failed case with what it catches, a
# function that raises or never returns or returns the wrong type one line each, a
# missing function "not written yet"; a module that does not load one line and exit 1,
# a wrong chapter one line and exit 2; the student's folder is left as it was; student
# code that ends the checker's process, hangs, or tampers with the checker fails and never
# passes; a dict-style Python chapter passes without an adapter, and a JavaScript one
# with settings of its own with the template adapter. And every function of every case
# file is read by a C++ test (one set of cases for both).
# Skipped without python3 or node (CI installs them: scripts/setup).
# Usage: check_runners.sh SOURCE_DIR WORK_DIR
set -euo pipefail
source_dir=$1 work=$2
rm -rf "$work"
mkdir -p "$work"
failed=0
check() {  # description, then a command that must succeed
  local what=$1
  shift
  if "$@"; then echo "ok: $what"; else echo "FAIL: $what"; failed=1; fi
}
says() { grep -qE -- "$1" "$work/out.txt"; }
python_runner=$source_dir/tools/check-functions/python/check-functions.py
js_runner=$source_dir/tools/check-functions/js/check-functions.js

echo "== every function of every case file is read by a C++ test"
for cases in "$source_dir"/tests/cases/*.json; do
  file=$(basename "$cases")
  for function in $(grep -o '"function": "[A-Za-z]*"' "$cases" | cut -d'"' -f4); do
    # A test file that reads the case file and names the function.
    readers=$(grep -rlF "CasesOf(\"$file\"" "$source_dir/tests" || true)
    check "$file: $function is read by a C++ test" \
      bash -c '[ -n "$1" ] && grep -qF "\"$2\"" $1' _ "$readers" "$function"
  done
done

run() {  # runs a runner into out.txt (stdout and stderr), its status in $status
  status=0
  "$@" >"$work/out.txt" 2>&1 || status=$?
  sed 's/^/    /' "$work/out.txt"
}

# Every reference of LANGUAGE (python or js) passes every case of its chapter (named in
# its first line), through RUNNER... (with the reference's adapter, if it has one).
references_pass() {
  local language=$1 reference chapter adapter
  shift
  for reference in "$source_dir/tools/check-functions/$language/reference/"*; do
    [[ $reference != *-adapter.js ]] || continue
    chapter=$(head -1 "$reference" | grep -o 'cases: [0-9][0-9]' | cut -d' ' -f2)
    adapter=()
    [ ! -f "${reference%.js}-adapter.js" ] || adapter=(--adapter "${reference%.js}-adapter.js")
    run "$@" "$chapter" "$reference" "${adapter[@]}"
    check "$(basename "$reference"): exit status 0" test $status -eq 0
    check "$(basename "$reference"): every function passed" \
      bash -c '! grep -qE "FAILED|not written" "$1"' _ "$work/out.txt"
  done
}

# The verdicts of a run on a student's chapter 2 with the mistakes planted below: y
# scaled by the width, IntersectRaySphere missing, and a TraceRay that loops forever,
# raises or returns "white". RAISED is how the runner words an exception at the
# student's FILE; WHITE how it prints the wrong value.
mistakes_reported() {
  local raised=$1 file=$2 white=$3
  check "mistakes: exit status 1" test $status -eq 1
  check "the failed case is named with what it catches" \
    says "^    case 4 of 02-basic-rays.json: y scaled by the canvas's width instead of its height"
  check "with what was expected and what it returned" \
    says "returned \[0.75, -0.3333333333, 1\], expected \[0.75, -0.5, 1\]"
  check "a function not written yet" says "^  IntersectRaySphere +not written yet \(5 cases\)"
  check "a case that never returns" says "^      did not return within 0.2 s"
  check "a case that raises, at the student's line" says "^      $raised: oops \(at $file:[0-9]+"
  check "a result of the wrong type" says "^      returned $white, not a color"
}

# A module that does not load, and a chapter without cases: one line each, exit 1 and 2.
bad_input_reported() {  # RUNNER... BROKEN_MODULE GOOD_MODULE
  local good=${*: -1} broken=${*: -2:1}
  local runner=("${@:1:$#-2}")
  run "${runner[@]}" 02 "$broken"
  check "a module that does not load: exit status 1, one line" \
    test $status -eq 1 -a "$(wc -l <"$work/out.txt")" -eq 1
  check "it names the error and the line" says "does not load: [A-Za-z]*Error: .*$(basename "$broken")"
  run "${runner[@]}" 99 "$good"
  check "a chapter without cases: exit status 2, one line" \
    test $status -eq 2 -a "$(wc -l <"$work/out.txt")" -eq 1
}

if command -v python3 >/dev/null; then
  echo "== Python: the references pass"
  references_pass python python3 "$python_runner"
  echo "== Python: a student's chapter 2 with mistakes"
  student=$work/python-student
  mkdir -p "$student"
  sed -e 's|y \* Vh / Ch|y * Vh / Cw|' \
      -e 's|^def IntersectRaySphere(|def IntersectRaySphereNotYet(|' \
      -e 's|^def TraceRay(O, D, t_min, t_max):|def TraceRay(O, D, t_min, t_max):\n    if t_min > 6:\n        while True:\n            pass\n    if t_max == 4:\n        raise ValueError("oops")\n    if t_max < 4:\n        return "white"\n    return TraceRayBook(O, D, t_min, t_max)\n\n\ndef TraceRayBook(O, D, t_min, t_max):|' \
      -e 's|IntersectRaySphere(O, D, sphere)$|IntersectRaySphereNotYet(O, D, sphere)|' \
      "$source_dir/tools/check-functions/python/reference/basic_rays.py" >"$student/mine.py"
  before=$(ls -AR "$student")
  run python3 "$python_runner" 02 "$student/mine.py" --time-limit 0.2
  mistakes_reported "raised ValueError" mine.py "'white'"
  echo "import no_such_module" >"$student/broken.py"
  bad_input_reported python3 "$python_runner" "$student/broken.py" "$student/mine.py"
  check "the student's folder has only what the test put there" \
    test "$before" = "$(ls -AR "$student" | grep -v '^broken.py$')"
else
  echo "SKIPPED: no python3 to run the Python runner (CI installs it: scripts/setup)"
fi

if command -v node >/dev/null; then
  echo "== JavaScript: the references pass"
  references_pass js node "$js_runner"
  echo "== JavaScript: a student's chapter 2 with mistakes"
  student=$work/js-student
  mkdir -p "$student"
  cp "$source_dir/tools/check-functions/js/reference/basic-rays-adapter.js" "$student/"
  sed -e 's|y \* Vh / Ch|y * Vh / Cw|' \
      -e 's|^function TraceRay(O, D, t_min, t_max) {|&\n  if (t_min > 6) for (;;) {}\n  if (t_max === 4) throw new RangeError("oops");\n  if (t_max < 4) return "white";|' \
      -e 's|IntersectRaySphere, TraceRay };|TraceRay };|' \
      "$source_dir/tools/check-functions/js/reference/basic-rays.js" >"$student/basic-rays.js"
  before=$(ls -AR "$student")
  run node "$js_runner" 02 "$student/basic-rays.js" --adapter "$student/basic-rays-adapter.js" --time-limit 0.2
  mistakes_reported "threw RangeError" basic-rays.js '"white"'
  echo 'throw new Error("at load")' >"$student/broken.js"
  bad_input_reported node "$js_runner" "$student/broken.js" "$student/basic-rays.js"
  check "the student's folder has only what the test put there" \
    test "$before" = "$(ls -AR "$student" | grep -v '^broken.js$')"
else
  echo "SKIPPED: no node to run the JavaScript runner (CI installs nodejs: scripts/setup)"
fi
# Student code that tries to end, hang or fool the checker: its cases fail (or it does not
# load), in about the time limit each, and it never passes. RUNNER... then, for each
# hostile module, MODULE DESCRIPTION.
if command -v python3 >/dev/null; then
  echo "== Python: student code that ends, hangs or tampers with the checker"
  hostile=$work/python-hostile
  mkdir -p "$hostile"
  base=$source_dir/tools/check-functions/python/reference/basic_rays.py
  echo 'import os; os._exit(0)' >"$hostile/exit_at_import.py"
  { cat "$base"; printf '\ndef CanvasToViewport(x, y):\n    import os\n    os._exit(0)\n'; } >"$hostile/exit_in_function.py"
  { cat "$base"; printf '\nimport signal\nsignal.signal(signal.SIGALRM, signal.SIG_IGN)\n\n\ndef CanvasToViewport(x, y):\n    while True:\n        try:\n            while True:\n                pass\n        except BaseException:\n            pass\n'; } >"$hostile/endless_loop.py"
  { cat "$base"; printf '\ndef CanvasToViewport(x, y):\n    def ones():\n        while True:\n            yield 1.0\n    return ones()\n'; } >"$hostile/endless_generator.py"
  { cat "$base"; printf '\nimport builtins, sys\nbuiltins.abs = lambda value: 0\nif hasattr(sys.modules["__main__"], "run_case"):\n    sys.modules["__main__"].run_case = lambda *a, **k: {"values": [0, 0, 1]}\n\n\ndef CanvasToViewport(x, y):\n    return (9, 9, 9)\n'; } >"$hostile/tampers.py"
  run python3 "$python_runner" 02 "$hostile/exit_at_import.py"
  check "Python: os._exit(0) at import: does not load, exit status 1" \
    test $status -eq 1 -a "$(wc -l <"$work/out.txt")" -eq 1
  check "it says the module ended the process" says "ended the process \(exit status 0\) while loading"
  for name in exit_in_function endless_loop endless_generator tampers; do
    start=$SECONDS
    run python3 "$python_runner" 02 "$hostile/$name.py" --time-limit 0.5
    check "Python, $name: exit status 1" test $status -eq 1
    check "Python, $name: CanvasToViewport failed every case" says "^  CanvasToViewport +FAILED [45] of 5 cases"
    [ $name = tampers ] ||
      check "Python, $name: the other functions are still judged" says "^  TraceRay +passed \(9 cases\)"
    check "Python, $name: within 15 s" test $((SECONDS - start)) -le 15
  done
  for chapter in '*' /etc 2; do
    run python3 "$python_runner" "$chapter" "$base"
    check "Python: chapter '$chapter': exit status 2, one line" \
      test $status -eq 2 -a "$(wc -l <"$work/out.txt")" -eq 1
  done
  echo "== Python: a chapter written with dicts, the book's globals, no adapter"
  run python3 "$python_runner" 02 "$source_dir/tests/check-functions/students/dict_style.py"
  check "the dict-style chapter passes without an adapter" test $status -eq 0
  cp "$source_dir/tests/check-functions/students/dict_style.py" "$hostile/own_globals.py"
  sed -i 's/\bscene\b/SPHERES_SCENE/g' "$hostile/own_globals.py"
  run python3 "$python_runner" 02 "$hostile/own_globals.py"
  check "one keeping its own globals fails, told which the checker set" \
    says "^    note: the checker set scene, BACKGROUND_COLOR on your module before these cases"
  python3 "$python_runner" --adapter-template >"$hostile/adapter.py"
  check "--adapter-template prints an adapter that loads" python3 -c "import ast, sys; ast.parse(open(sys.argv[1]).read())" "$hostile/adapter.py"
fi
if command -v node >/dev/null; then
  echo "== JavaScript: student code that ends, hangs or tampers with the checker"
  hostile=$work/js-hostile
  mkdir -p "$hostile"
  base=$source_dir/tools/check-functions/js/reference/basic-rays.js
  cp "$source_dir/tools/check-functions/js/reference/basic-rays-adapter.js" "$hostile/adapter.js"
  echo 'process.exit(0);' >"$hostile/exit-at-import.js"
  with() {  # NAME CODE: the reference, its CanvasToViewport replaced by CODE
    sed "s|^function CanvasToViewport(x, y) {|function CanvasToViewport(x, y) {\n$2|" "$base" >"$hostile/$1.js"
    sed -i "s|\./basic-rays\.js|./$1.js|" "$hostile/adapter.js"
    cp "$hostile/adapter.js" "$hostile/$1-adapter.js"
    sed -i "s|\./$1\.js|./basic-rays.js|" "$hostile/adapter.js"
  }
  with exit-in-function '  process.exit(0);'
  with endless-loop '  for (;;) {}'
  with tampers '  Math.abs = () => 0; if (process.send) process.send({ done: true, id: 1, values: [0, 0, 1] }); return [9, 9, 9];'
  run node "$js_runner" 02 "$hostile/exit-at-import.js"
  check "JavaScript: process.exit(0) at import: does not load, exit status 1" \
    test $status -eq 1 -a "$(wc -l <"$work/out.txt")" -eq 1
  for name in exit-in-function endless-loop tampers; do
    start=$SECONDS
    run node "$js_runner" 02 "$hostile/$name.js" --adapter "$hostile/$name-adapter.js" --time-limit 0.5
    check "JavaScript, $name: exit status 1" test $status -eq 1
    check "JavaScript, $name: CanvasToViewport failed every case" says "^  CanvasToViewport +FAILED [45] of 5 cases"
    [ $name = tampers ] ||
      check "JavaScript, $name: the other functions are still judged" says "^  TraceRay +passed \(9 cases\)"
    check "JavaScript, $name: within 15 s" test $((SECONDS - start)) -le 15
  done
  run node "$js_runner" 02 "$base" --adapter
  check "JavaScript: --adapter without a file: exit status 2, one line" \
    test $status -eq 2 -a "$(wc -l <"$work/out.txt")" -eq 1
  echo "== JavaScript: a chapter with settings of its own, and the template adapter"
  students=$source_dir/tests/check-functions/students
  run node "$js_runner" 02 "$students/own-settings.js"
  check "without an adapter it fails, told which globals the checker set" \
    says "^    note: the checker set Cw, Ch, Vw, Vh, d on globalThis before these cases"
  cp "$students/own-settings.js" "$hostile/"
  node "$js_runner" --adapter-template | sed 's|\./raytracer\.js|./own-settings.js|' >"$hostile/own-adapter.js"
  run node "$js_runner" 02 "$hostile/own-settings.js" --adapter "$hostile/own-adapter.js"
  check "with the template adapter, its require pointed at it, it passes" test $status -eq 0
fi

if command -v python3 >/dev/null && command -v node >/dev/null; then
  echo "== docs/students.md: its commands as written, on its layout"
  export HOME=$work/home
  mkdir -p ~/my-cgfs/02-basic-rays ~/my-cgfs-js/02-basic-rays
  cp "$source_dir/tools/check-functions/python/reference/basic_rays.py" ~/my-cgfs/02-basic-rays/raytracer.py
  cp "$source_dir/tools/check-functions/js/reference/basic-rays.js" ~/my-cgfs-js/02-basic-rays/raytracer.js
  sed 's|\./basic-rays\.js|./raytracer.js|' "$source_dir/tools/check-functions/js/reference/basic-rays-adapter.js" \
    >~/my-cgfs-js/02-basic-rays/adapter.js
  # The fenced block after the marker: the commands, one a line.
  mapfile -t commands < <(awk '/<!-- checkers:/ { marked = 1 } marked && /^```sh/ { inside = 1; next }
    inside && /^```/ { exit } inside { print }' "$source_dir/docs/students.md")
  check "docs/students.md gives both commands" test ${#commands[@]} -eq 2
  for command in "${commands[@]}"; do
    (cd "$source_dir" && eval "$command") >"$work/out.txt" 2>&1 && status=0 || status=$?
    check "as documented: $command" test $status -eq 0
    check "every function passed" bash -c '[ "$(grep -c " passed (" "$1")" -eq 3 ]' _ "$work/out.txt"
  done
  # The worked example: its output is what the command prints for the mistake it shows.
  sed -i 's|y \* Vh / Ch|y * Vh / Cw|' ~/my-cgfs/02-basic-rays/raytracer.py
  example=$(awk '/^\$ python3 tools\/check-functions/ { inside = 1; sub(/^\$ /, ""); print; next }
    inside && /^```/ { exit } inside { print }' "$source_dir/docs/students.md")
  (cd "$source_dir" && eval "$(head -1 <<<"$example")") >"$work/out.txt" 2>&1 || true
  check "the worked example's output is what the checker prints" \
    diff <(tail -n +2 <<<"$example") "$work/out.txt"
fi
[ $failed -eq 0 ] && echo "PASS: the runners check functions as documented"
exit $failed
