#!/usr/bin/env bash
# The function checker (tools/check-functions), as a student uses it, in Python and in
# JavaScript: our references of every chapter pass; planted mistakes fail the case that
# catches them, in the case's words; a chapter written with names of its own is told so
# first, with those names, and the per-case headings are held back; a default argument
# bound at definition is named with its fix; the demos' style (a plain script, a page)
# passes where it computes what the book says and says where the demos differ; earlier
# chapters' functions are checked again where the chapter keeps them; nothing the
# student's code does because of the checker's arguments writes a file; bad input is one
# line. Every function of every case file is read by a C++ test, and the case files'
# contracts between chapters hold. Skipped without node (CI installs it: scripts/setup);
# the Python parts without python3. PART: `references` runs our references alone (the
# deep checks' mistakes part), `behaviour` the rest (the test command); without it, both.
# Usage: check_checkers.sh SOURCE_DIR WORK_DIR [references|behaviour]
set -euo pipefail
source_dir=$1 work=$2 part=${3:-both}
rm -rf "$work"
mkdir -p "$work"
failed=0
check() {  # description, then a command that must succeed
  local what=$1
  shift
  if "$@"; then echo "ok: $what"; else echo "FAIL: $what"; failed=1; fi
}
says() { grep -qE -- "$1" "$work/out.txt"; }
lacks() { ! grep -qE -- "$1" "$work/out.txt"; }
checker=$source_dir/tools/check-functions/check-functions.js
reference=$source_dir/tools/check-functions/reference
students=$source_dir/tests/check-functions/students
students_before=$(ls -A "$students")
run() {  # runs the checker into out.txt (stdout and stderr), its status in $status
  status=0
  node "$checker" "$@" >"$work/out.txt" 2>&1 || status=$?
  sed 's/^/    /' "$work/out.txt"
}
one_line() { test "$(wc -l <"$work/out.txt")" -eq 1; }

if [ "$part" != references ]; then
  echo "== every function of every case file is read by a C++ test"
  for cases in "$source_dir"/tests/cases/*.json; do
    file=$(basename "$cases")
    for function in $(grep -o '"function": "[A-Za-z]*"' "$cases" | cut -d'"' -f4); do
      readers=$(grep -rlF "CasesOf(\"$file\"" "$source_dir/tests" || true)
      check "$file: $function is read by a C++ test" \
        bash -c '[ -n "$1" ] && grep -qF "\"$2\"" $1' _ "$readers" "$function"
    done
  done
fi

if ! command -v node >/dev/null; then
  echo "SKIPPED: no node to run the checker (CI installs nodejs: scripts/setup)"
  [ $failed -ne 0 ] || [ "$part" = references ] || echo "PASS: the case files are read by C++ tests"
  exit $failed
fi
if [ "$part" != references ]; then
  echo "== the case files' contracts between chapters"
  check "every kept function has cases there and is declared by the chapter that keeps it" \
    node "$source_dir/tests/check-functions/check_case_files.mjs" "$source_dir"
fi

have_python=0
command -v python3 >/dev/null && have_python=1
languages=(js)
[ $have_python -eq 1 ] && languages=(python js)

reference_languages=("${languages[@]}")
if [ "$part" = behaviour ]; then reference_languages=(); fi
[ ${#reference_languages[@]} -eq 0 ] || echo "== the references pass, every chapter"
for language in "${reference_languages[@]}"; do
  for file in "$reference/$language/"*; do
    [[ $file != *-adapter.js ]] || continue
    chapter=$(head -1 "$file" | grep -o 'cases: [0-9][0-9]' | cut -d' ' -f2)
    adapter=()
    [ ! -f "${file%.js}-adapter.js" ] || adapter=(--adapter "${file%.js}-adapter.js")
    run "$chapter" "$file" "${adapter[@]}"
    check "$(basename "$file"): exit status 0, nothing failed or missing" \
      bash -c '[ "$1" -eq 0 ] && ! grep -qE "FAILED|not written" "$2"' _ $status "$work/out.txt"
  done
done

if [ "$part" = references ]; then
  [ $failed -eq 0 ] && echo "PASS: our references pass every chapter"
  exit $failed
fi

# A student's chapter 2 with mistakes planted: y scaled by the width, IntersectRaySphere
# missing, and a TraceRay that loops forever, raises or returns "white".
mistakes_reported() {  # RAISED: how the error is worded, at FILE
  local raised=$1 file=$2
  check "mistakes: exit status 1" test $status -eq 1
  check "the failed case is named with what it catches" \
    says "^    case 4 of 02-basic-rays.json: y scaled by the canvas's width instead of its height"
  check "with what was expected and what it returned" \
    says "returned \[0.75, -0.3333333333, 1\], expected \[0.75, -0.5, 1\]"
  check "a function not written yet" says "^  IntersectRaySphere +not written yet \(5 cases\)"
  check "a case that never returns" says "^      did not return within 0.5 s"
  check "a case that raises, at the student's line" says "^      $raised: oops \(at $file:[0-9]+"
  check "a result of the wrong type" says '^      returned "white", not a colour'
}
if [ $have_python -eq 1 ]; then
  echo "== Python: a student's chapter 2 with mistakes"
  student=$work/python-student
  mkdir -p "$student"
  sed -e 's|y \* Vh / Ch|y * Vh / Cw|' \
      -e 's|^def IntersectRaySphere(|def IntersectRaySphereNotYet(|' \
      -e 's|^def TraceRay(O, D, t_min, t_max):|def TraceRay(O, D, t_min, t_max):\n    if t_min > 6:\n        while True:\n            pass\n    if t_max == 4:\n        raise ValueError("oops")\n    if t_max < 4:\n        return "white"\n    return TraceRayBook(O, D, t_min, t_max)\n\n\ndef TraceRayBook(O, D, t_min, t_max):|' \
      -e 's|IntersectRaySphere(O, D, sphere)$|IntersectRaySphereNotYet(O, D, sphere)|' \
      "$reference/python/basic_rays.py" >"$student/mine.py"
  run 02 "$student/mine.py" --time-limit 0.5
  mistakes_reported "raised ValueError" mine.py
fi
echo "== JavaScript: a student's chapter 2 with mistakes"
student=$work/js-student
mkdir -p "$student"
sed -e 's|y \* Vh / Ch|y * Vh / Cw|' \
    -e 's|^function IntersectRaySphere(|function IntersectRaySphereNotYet(|' \
    -e 's|IntersectRaySphere(O, D, sphere);|IntersectRaySphereNotYet(O, D, sphere);|' \
    -e 's|^function TraceRay(O, D, t_min, t_max) {|&\n  if (t_min > 6) for (;;) {}\n  if (t_max === 4) throw new RangeError("oops");\n  if (t_max < 4) return "white";|' \
    -e 's|IntersectRaySphere, TraceRay };|TraceRay };|' \
    "$reference/js/basic-rays.js" >"$student/basic-rays.js"
run 02 "$student/basic-rays.js" --time-limit 0.5
mistakes_reported "threw RangeError" basic-rays.js

echo "== a function with nothing in its body yet, as a chapter page's starter leaves it, is not written yet"
printf 'def CanvasToViewport(x, y):\n    pass\n\n\ndef IntersectRaySphere(O, D, sphere):\n    """Listing 2-3."""\n' >"$work/starter.py"
printf 'function CanvasToViewport(x, y) {\n}\nconst IntersectRaySphere = (O, D, sphere) => {};\n' >"$work/starter.js"
for file in "$work/starter.js" $([ $have_python -eq 0 ] || echo "$work/starter.py"); do
  run 02 "$file"
  check "$(basename "$file"): each empty function is not written yet" \
    test "$(grep -cE "^  (CanvasToViewport|IntersectRaySphere) +not written yet \([0-9]+ cases\)" "$work/out.txt")" -eq 2
done

echo "== bad input: one line each"
echo 'throw new Error("at load")' >"$work/broken.js"
printf 'function CanvasToViewport(x, y) {\n  return [x,, y;\n}\n' >"$work/syntax.js"
printf 'Cw = 600\n\n\ndef CanvasToViewport(x, y)\n    return x\n' >"$work/syntax.py"
printf 'function Hello() {}\nconsole.log("hello");\n' >"$work/none.js"
run 02 "$work/broken.js"
check "a file that does not load: exit status 1, one line naming the error and line" \
  bash -c '[ "$1" -eq 1 ] && [ "$(wc -l <"$2")" -eq 1 ] && grep -q "does not load: Error: at load (at broken.js" "$2"' _ $status "$work/out.txt"
run 02 "$work/syntax.js"
check "a JavaScript syntax error names its line" bash -c '[ "$1" -eq 1 ] && grep -q "SyntaxError: .*(at syntax.js:2)" "$2"' _ $status "$work/out.txt"
if [ $have_python -eq 1 ]; then
  run 02 "$work/syntax.py"
  check "a Python syntax error names its line" bash -c '[ "$1" -eq 1 ] && grep -q "SyntaxError: .*(at syntax.py:4)" "$2"' _ $status "$work/out.txt"
fi
run 02 "$work/none.js"
check "a file with none of the chapter's functions: exit status 1, one line saying how to write them" \
  bash -c '[ "$1" -eq 1 ] && [ "$(wc -l <"$2")" -eq 1 ] && grep -q "defines none of 02-basic-rays.s functions" "$2"' _ $status "$work/out.txt"
for arguments in "99 $reference/js/lines.js" "* $reference/js/lines.js" "02" "02 $work/no-such.js" "02 $work" \
  "02 $source_dir/README.md" "02 $reference/js/lines.js --time-limit abc" "02 $reference/js/lines.js --time-limit" \
  "02 $reference/js/lines.js --adapter" "02 $reference/js/lines.js --bogus" "--adapter-template 02"; do
  # shellcheck disable=SC2086
  run $arguments
  check "'$arguments': exit status 2, one line" bash -c '[ "$1" -eq 2 ] && [ "$(wc -l <"$2")" -eq 1 ]' _ $status "$work/out.txt"
done
run --help
check "--help: exit status 0, the usage" bash -c '[ "$1" -eq 0 ] && grep -q "^usage: check-functions.js CHAPTER YOUR_FILE" "$2"' _ $status "$work/out.txt"

if [ $have_python -eq 1 ]; then
  echo "== Python: names of its own, told first, with the adapter that fixes it"
  run 02 "$students/own_names.py"
  check "exit status 1" test $status -eq 1
  check "the block opens with one line naming the student's names and what to do" \
    says "^    CanvasToViewport reads your module's \`CANVAS_HEIGHT\`, \`CANVAS_WIDTH\`, \`PROJECTION_PLANE_D\` and \`VIEWPORT_SIZE\`, so the canvas's size and the viewport that each case gives never reach it: the checker sets \`Cw\`, \`Ch\`, \`Vw\`, \`Vh\` and \`d\`"
  check "the line names the adapter template for this file" says "\`--adapter-template 02 own_names.py\` prints one for this file"
  check "no heading names a mistake it did not make" lacks "y scaled by the canvas's width|z fixed at 1"
  check "the failed cases are marked as consequences" says "^    case 4 of 02-basic-rays.json \(a consequence of the line above\): returned"
  node "$checker" --adapter-template 02 "$students/own_names.py" >"$work/own_names_adapter.py"
  check "--adapter-template fills in the file's own names" \
    bash -c 'grep -q "module.CANVAS_WIDTH = given\[\"canvas\"\]\[\"width\"\]" "$1" && grep -q "module.VIEWPORT_SIZE = " "$1" && grep -q "module.BACKGROUND = " "$1"' _ "$work/own_names_adapter.py"
  cp "$students/own_names.py" "$work/own_names.py"
  run 02 "$work/own_names.py" --adapter "$work/own_names_adapter.py"
  check "with that adapter only the non-square viewport fails" test "$(grep -c FAILED "$work/out.txt")" -eq 1
  check "(that one)" says "^  CanvasToViewport +FAILED 1 of 6 cases"
  check "told why: its viewport is square" says "case 4 of 02-basic-rays.json: your viewport is square \(\`VIEWPORT_SIZE\`\)"
  check "with an adapter, no line says the checker set anything" lacks "the checker set"
  echo "== Python: a default argument bound when the def ran"
  run 02 "$students/bound_default.py"
  check "named as such, with the change that fixes it" \
    says "^    TraceRay's default \`spheres=SPHERES\` is taken once, when \`def TraceRay\` runs, so what a case gives never reaches it: write \`spheres=None\` and begin TraceRay with \`if spheres is None: spheres = SPHERES\`"
  check "and nothing says to give an adapter there" bash -c '! grep -A1 "TraceRay .*FAILED" "$1" | grep -q "adapter"' _ "$work/out.txt"
  echo "== Python: a chapter written with dicts and the book's globals passes as it is"
  run 02 "$students/dict_style.py"
  check "exit status 0" test $status -eq 0
  if [ -x /usr/bin/python3 ]; then
    echo "== Python: the python3 on PATH a link to the system's, from a folder of the user's (~/bin)"
    mkdir -p "$work/user-bin"
    ln -sf /usr/bin/python3 "$work/user-bin/python3"
    PATH=$work/user-bin:$PATH run 02 "$students/dict_style.py"
    check "exit status 0: the link is there in the sandbox too" test $status -eq 0
  fi
fi

echo "== JavaScript in the demos' style: a plain script and a page"
run 03 "$students/demo-style.js"
check "the plain script's ComputeLighting passes without an edit" says "^  ComputeLighting +passed \(7 cases\)"
check "and its TraceRay" says "^  TraceRay +passed \(6 cases\)"
check "the one case its square viewport cannot pass says that the demos and the book differ" \
  says "^    case 4 of 02-basic-rays.json: this is where the demos and the book differ: the demos' viewport is square \(viewport_size\)"
check "nothing else fails" test "$(grep -c "FAILED" "$work/out.txt")" -eq 1
run 02 "$students/demo-page.html"
check "the page's CanvasToViewport(p2d) is called as the demos call it, with one point [x, y]" \
  says "^      CanvasToViewport\(p2d\) with "
check "the page's TraceRay passes" says "^  TraceRay +passed \(9 cases\)"
check "and its IntersectRaySphere" says "^  IntersectRaySphere +passed \(5 cases\)"
check "nothing but the square viewport's case fails" test "$(grep -c FAILED "$work/out.txt")" -eq 1
sed -e 's|p2d\[1\] \* viewport_size / canvas.height|p2d[1] * viewport_size / canvas.width|' "$students/demo-page.html" >"$work/y-by-width.html"
run 02 "$work/y-by-width.html"
check "y scaled by the width on the demos' square viewport is caught, as a mistake, not as where the demos differ" \
  says "^    case 6 of 02-basic-rays.json: y scaled by the canvas's width instead of its height, on a square viewport"
sed -e 's/min_t <= ts\[\([01]\)\] && ts\[\1\] <= max_t/min_t < ts[\1] \&\& ts[\1] < max_t/' "$students/demo-page.html" >"$work/open-interval.html"
run 02 "$work/open-interval.html"
check "a page with the demos' open interval fails the two cases on the interval's ends" says "^  TraceRay +FAILED 2 of 9 cases"
check "each told where the demos and the book differ" \
  test "$(grep -c "this is where the demos and the book differ: the demos test min_t < t < max_t" "$work/out.txt")" -eq 2
sed -e 's/function ComputeLighting(point, normal, view, specular) {/function ComputeLighting(point, normal) {\n  const specular = -1, view = null;/' \
    -e 's/ComputeLighting(point, normal, direction.mul(-1), closest_sphere.specular)/ComputeLighting(point, normal)/' \
  "$students/demo-style.js" >"$work/listing-3-1.js"
run 03 "$work/listing-3-1.js"
check "Listing 3-1's ComputeLighting(P, N) is checked on the matte cases, and told which listing the others need" \
  says "^  ComputeLighting +passed \(4 of 7 cases\)" 
check "(the line naming both signatures)" says "only its cases for ComputeLighting\(P, N\) \(Listing 3-1, \"Diffuse Reflection\"\): the other 3 call ComputeLighting\(P, N, V, s\)"

echo "== every chapter so far: chapter 3 with chapter 2's roots swapped, in a file it imports"
for language in "${languages[@]}"; do
  swapped=$work/swapped-$language
  mkdir -p "$swapped"
  # Chapter 2's file with its roots swapped, and chapter 3's without its own
  # IntersectRaySphere: it imports chapter 2's.
  if [ "$language" = python ]; then
    sed 's|    return t1, t2|    return t2, t1|' "$reference/python/basic_rays.py" >"$swapped/basic_rays.py"
    awk '/^# Listing 2-3/ {next} /^def IntersectRaySphere/ {skip=1; next} skip && /^[^ \t]/ {skip=0} !skip' \
      "$reference/python/light.py" | sed 's|^import math$|import math\n\nfrom basic_rays import IntersectRaySphere|' >"$swapped/light.py"
    file=$swapped/light.py
  else
    { sed 's|  return \[t1, t2\];|  return [t2, t1];|' "$reference/js/basic-rays.js"
      echo 'module.exports = { IntersectRaySphere };'; } >"$swapped/basic-rays.js"
    awk '/^\/\/ Listing 2-3/ {next} /^function IntersectRaySphere/ {skip=1; next} skip && /^}/ {skip=0; next} !skip' \
      "$reference/js/light.js" | sed 's|^"use strict";$|&\nconst { IntersectRaySphere } = require("./basic-rays.js");|' >"$swapped/light.js"
    file=$swapped/light.js
  fi
  run 03 "$file"
  check "$language: exit status 1" test $status -eq 1
  check "$language: chapter 2's functions are checked again, under their chapter" says "^02-basic-rays, as 03-light keeps it:"
  check "$language: its IntersectRaySphere fails" says "^  IntersectRaySphere +FAILED 3 of 5 cases"
  check "$language: chapter 2's TraceRay is not, and the report says why once" \
    test "$(grep -c "^  TraceRay .*not checked against 02-basic-rays.json: chapter 3's TraceRay lights what it finds" "$work/out.txt")" -eq 1
done

echo "== nothing of the checker reaches the student's code: a main block on its arguments writes nothing"
runs_in=$work/cwd
mkdir -p "$runs_in"
cp "$students/own_names.py" "$students/demo-style.js" "$runs_in/"
before=$(find "$work" | sort)
for sandbox in 1 0; do
  for file in "${languages[@]/python/own_names.py}"; do
    [ "$file" = js ] && file=demo-style.js
    chapter=02
    [ "$file" = demo-style.js ] && chapter=03
    (cd "$runs_in" && if [ $sandbox = 0 ]; then export CGFS_NO_SANDBOX=1; fi; node "$checker" "$chapter" "$file" >/dev/null 2>&1 || true)
  done
done
check "no file written anywhere under the work folder, with or without the sandbox" test "$before" = "$(find "$work" | sort)"
check "the students' folder in the repository is as it was" test "$students_before" = "$(ls -A "$students")"

echo "== lights carry only their type's fields"
cat >"$work/lights.js" <<'EOF'
// A reader's ComputeLighting that tells point lights from directional ones by the field they have.
const sub = (a, b) => a.map((v, i) => v - b[i]);
const dot = (a, b) => a.reduce((s, v, i) => s + v * b[i], 0);
const len = (a) => Math.sqrt(dot(a, a));
function ComputeLighting(P, N, V, s) {
  let i = 0;
  for (const light of scene.lights) {
    if (light.type === "ambient") { i += light.intensity; continue; }
    const L = light.position ? sub(light.position, P) : light.direction;
    const nl = dot(N, L);
    if (nl > 0) i += light.intensity * nl / (len(N) * len(L));
    if (s !== -1) {
      const R = sub(N.map((v) => 2 * nl * v), L);
      const rv = dot(R, V);
      if (rv > 0) i += light.intensity * Math.pow(rv / (len(R) * len(V)), s);
    }
  }
  return i;
}
EOF
run 03 "$work/lights.js"
check "light.position || light.direction tells them apart: every ComputeLighting case passes" says "^  ComputeLighting +passed \(7 cases\)"

echo "== a scene of the reader's own, with a field the checker's scene does not have"
sed 's/background_color/background/g' "$reference/js/basic-rays.js" >"$work/own_scene.js"
run 02 "$work/own_scene.js"
check "JavaScript: the field read from the checker's scene is said first, as Python's AttributeError is" \
  says "^    TraceRay reads \`scene.background\`, which the checker's scene does not have"
check "and the cases are its consequences" \
  says "^    case 8 of 02-basic-rays.json \(a consequence of the line above\): returned null, not a colour"
cat >"$work/own_scene_adapter.js" <<'EOF'
module.exports = {
  setup(module, given, adapter) {
    if (given.scene) module.scene.background = adapter.color(given.scene.background_color, adapter);
  },
};
EOF
run 02 "$work/own_scene.js" --adapter "$work/own_scene_adapter.js"
check "with the adapter the note asks for, the chapter passes" says "^chapter: complete"
run 02 "$reference/js/basic-rays.js"
check "a chapter that reads only the book's fields gets no such note" lacks "reads \`scene\."

echo "== a chapter's own types, a page's script saved as .js, an ES module, a file written at load"
styles=$work/styles
mkdir -p "$styles"
cat >"$styles/vectors.js" <<'EOF'
// A browser script with a vector class of its own.
const canvas = document.getElementById("canvas");
class Vec3D {
  constructor(x, y, z) { Object.assign(this, { x, y, z }); }
  dot(v) { return this.x * v.x + this.y * v.y + this.z * v.z; }
  sub(v) { return new Vec3D(this.x - v.x, this.y - v.y, this.z - v.z); }
}
function IntersectRaySphere(O, D, sphere) {
  const CO = O.sub(sphere.center), a = D.dot(D), b = 2 * CO.dot(D), c = CO.dot(CO) - sphere.radius ** 2;
  const disc = b * b - 4 * a * c;
  if (disc < 0) return [Infinity, Infinity];
  return [(-b + Math.sqrt(disc)) / (2 * a), (-b - Math.sqrt(disc)) / (2 * a)];
}
EOF
run 02 "$styles/vectors.js"
check "a script that reaches for document loads (the page's stand-in)" test $status -eq 1
check "a method the checker's vectors lack is said once, first, naming the call" \
  says "^    IntersectRaySphere calls \`O.sub\`, which what the checker gives it does not have"
check "and the cases are its consequences" \
  says "^    case 1 of 02-basic-rays.json \(a consequence of the line above\): threw TypeError: O.sub is not a function"
node "$checker" --adapter-template 02 "$styles/vectors.js" >"$styles/vectors-adapter.js"
check "--adapter-template makes the vectors with its Vec3D" grep -qF "vector: ([a, b, c]) => new Vec3D(a, b, c)" "$styles/vectors-adapter.js"
run 02 "$styles/vectors.js" --adapter "$styles/vectors-adapter.js"
check "with it, IntersectRaySphere passes" says "^  IntersectRaySphere +passed \(5 cases\)"
printf 'const canvasWidth = 600, canvasHeight = 600, size = 1, distance = 1;\nexport function CanvasToViewport(x, y) {\n  return [x * size / canvasWidth, y * size / canvasHeight, distance];\n}\n' >"$styles/module.mjs"
run 02 "$styles/module.mjs"
check "an ES module's own names are named, as a script's are, with the adapter that sets them" \
  says "reads your \`canvasHeight\`, \`canvasWidth\`, \`distance\` and \`size\`.*give an adapter that sets yours \(\`--adapter-template 02 module.mjs\`"
# The book's names in an ES module, declared and exported, with a main guard that must
# stay shut: the case's canvas and viewport reach them (Node.js 20.6 and newer).
printf 'import { fileURLToPath } from "node:url";\nexport let Cw = 600, Ch = 600;\nconst Vw = 1, Vh = 1, d = 1;\nexport function CanvasToViewport(x, y) {\n  return [x * Vw / Cw, y * Vh / Ch, d];\n}\nif (process.argv[1] === fileURLToPath(import.meta.url)) throw new Error("main ran");\n' >"$styles/book-module.mjs"
run 02 "$styles/book-module.mjs"
if node -e 'process.exit(typeof require("module").register === "function" ? 0 : 1)'; then
  check "an ES module's own Cw, Vw and d (let and const) are set for each case, its main guard shut" \
    says "^  CanvasToViewport +passed \(6 cases\)"
fi
printf 'require("fs").writeFileSync("out.ppm", "P3");\nfunction CanvasToViewport(x, y) { return [0, 0, 1]; }\n' >"$styles/writes.js"
run 02 "$styles/writes.js"
check "a script that writes a file as it loads is told where that belongs, in one line" one_line
check "(that line)" says "it writes a file as it loads, which it may not here; keep that under if \(require.main === module\)"
if [ $have_python -eq 1 ]; then
  printf 'class V:\n    def __init__(self, x, y, z):\n        self.x, self.y, self.z = x, y, z\n\n    def sub(self, o):\n        return V(self.x - o.x, self.y - o.y, self.z - o.z)\n\n\ndef IntersectRaySphere(O, D, sphere):\n    CO = O.sub(sphere.center)\n    return (0, 0)\n' >"$styles/own_vector.py"
  run 02 "$styles/own_vector.py"
  check "Python: a method the checker's values lack is said first" \
    says "^    IntersectRaySphere calls \`.sub\`, which what the checker gives it does not have"
  node "$checker" --adapter-template 02 "$styles/own_vector.py" >"$styles/own_vector_adapter.py"
  check "Python: --adapter-template imports its V" grep -qx "from own_vector import V" "$styles/own_vector_adapter.py"
  check "Python: and makes vectors with it" grep -qx "    return V(\*value)" "$styles/own_vector_adapter.py"
  printf 'open("out.ppm", "w").write("P3")\n\n\ndef CanvasToViewport(x, y):\n    return (0, 0, 1)\n' >"$styles/writes.py"
  run 02 "$styles/writes.py"
  check "Python: a module that writes a file as it loads is told where that belongs" \
    says 'keep that under if __name__ == "__main__":'
fi

echo "== docs/students.md: its commands as written, on its layout"
export HOME=$work/home
mkdir -p ~/my-cgfs/02-basic-rays ~/my-cgfs-js/02-basic-rays
cp "$reference/js/basic-rays.js" ~/my-cgfs-js/02-basic-rays/raytracer.js
if [ $have_python -eq 1 ]; then
  cp "$reference/python/basic_rays.py" ~/my-cgfs/02-basic-rays/raytracer.py
fi
# The fenced block after the marker: the commands, one a line.
mapfile -t commands < <(awk '/<!-- checkers:/ { marked = 1 } marked && /^```sh/ { inside = 1; next }
  inside && /^```/ { exit } inside { print }' "$source_dir/docs/students.md")
check "docs/students.md gives both commands" test ${#commands[@]} -eq 2
for command in "${commands[@]}"; do
  [ $have_python -eq 1 ] || [[ $command != *.py* ]] || continue
  (cd "$source_dir" && eval "$command") >"$work/out.txt" 2>&1 && status=0 || status=$?
  check "as documented: $command" test $status -eq 0
  check "every function passed" bash -c '[ "$(grep -c " passed (" "$1")" -eq 3 ]' _ "$work/out.txt"
done
# Each worked example: its output is what the command prints, on the file it shows.
if [ $have_python -eq 1 ]; then
  sed -i 's|y \* Vh / Ch|y * Vh / Cw|' ~/my-cgfs/02-basic-rays/raytracer.py
  cp "$students/own_names.py" ~/my-cgfs/02-basic-rays/own_names.py
  cp "$students/demo-page.html" ~/my-cgfs-js/02-basic-rays/page.html
  awk -v work="$work" '/<!-- example: checker / { name = $4; next } name && /^```$/ && inside { inside = 0; name = ""; next }
    name && /^```/ { inside = 1; out = work "/example-" name; next }
    inside { print > out }' "$source_dir/docs/students.md"
  for example in $(find "$work" -maxdepth 1 -name 'example-*' | sort); do
    command=$(head -1 "$example" | sed 's/^\$ //')
    (cd "$source_dir" && eval "$command") >"$work/out.txt" 2>&1 || true
    check "the worked example $(basename "$example"): its output is what the checker prints" \
      diff <(tail -n +2 "$example") "$work/out.txt"
  done
  check "docs/students.md has its worked examples" test "$(find "$work" -name 'example-*' | wc -l)" -ge 4
fi
[ $failed -eq 0 ] && echo "PASS: the checker checks functions as documented"
exit $failed
