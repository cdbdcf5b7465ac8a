#!/usr/bin/env bash
# Proves the student path of docs/students.md, with exactly its layout and commands:
# a student folder holding raytracer.h, raytracer.cpp and scenes.cpp for chapter 02
# (no main.cpp, no scenes.h), judged by `scripts/test-student ~/my-cgfs`, run in a
# copy of the repository with HOME pointing at a scratch folder.
#   - a faithful copy passes, and render writes into build-student/my-cgfs/out/;
#   - a half-written copy (only CanvasToViewport and IntersectRaySphere) passes what
#     is written and reports the rest as not written yet, by name;
#   - a copy with one mistake fails, naming the test;
#   - a header or a definition with another signature than ours fails, naming both;
#   - chapter 02 copied forward as 03 without our new header is told to take it;
#   - a copy that does not compile fails with its first error, and ctest afterwards
#     does not pass; a faithful chapter beside it is tested all the same;
#   - a missing or misnamed folder gets one line and exit status 2, and so does a path
#     the build tools cannot carry;
#   - a header that includes /dev/zero stops the compiler at its memory limit, in the
#     build and in the tests' rebuild, and is reported as headers that do not compile;
#   - the five examples of `scripts/test-student` in docs/students.md (each under a line
#     "<!-- example: NAME -->") are these runs' command and output, word for word.
# Usage: check_student_build.sh SOURCE_DIR WORK_DIR
set -euo pipefail
source_dir=$1 work=$2
chapter=02-basic-rays

rm -rf "$work"
mkdir -p "$work/repo" "$work/home/my-cgfs/$chapter"
tar -C "$source_dir" --exclude='./build*' --exclude=./out --exclude=./.git -cf - . \
  | tar -C "$work/repo" -xf -
export HOME=$work/home
# The nested builds compile without optimisation (CMake takes CMAKE_BUILD_TYPE from the
# environment for a new build folder; None: no flags): what is tested here is the
# path, its messages and exit statuses, and the main build tests the optimised code.
# It takes a third less time.
export CMAKE_BUILD_TYPE=None
student=$HOME/my-cgfs/$chapter
ours=$source_dir/chapters/$chapter
cd "$work/repo"

failed=0
check() {  # description, then a command that must succeed
  local what=$1
  shift
  if "$@"; then echo "ok: $what"; else echo "FAIL: $what" >&2; failed=1; fi
}
run() {  # runs the documented command, output in $work/out.txt, status in $status
  status=0
  command="scripts/test-student $*"
  scripts/test-student "$@" >"$work/out.txt" 2>&1 || status=$?
  sed 's/^/    /' "$work/out.txt"
}
says() { grep -qE "$1" "$work/out.txt"; }
# The example of docs/students.md under the line "<!-- example: NAME -->" is the last
# run, command and output, with the student's home as ~ in the command and /home/you in
# the output, this copy of the repository as ~/cgfs, and the compiler's quotes as '.
shows_example() {
  local name=$1
  awk -v mark="<!-- example: $name -->" '$0 == mark { found = 1; next }
    found && /^```/ { if (inside) exit; inside = 1; next } inside { print }' \
    "$source_dir/docs/students.md" | sed "s/[‘’]/'/g" >"$work/example-$name.docs"
  { echo "\$ ${command//$HOME/\~}"; sed -e "s|$HOME|/home/you|g" -e "s|$work/repo|~/cgfs|g" \
      -e "s/[‘’]/'/g" "$work/out.txt"; } >"$work/example-$name.run"
  [ -s "$work/example-$name.docs" ] && diff "$work/example-$name.docs" "$work/example-$name.run"
}

echo "== the documented layout: raytracer.h, raytracer.cpp, scenes.cpp"
cp "$ours/raytracer.h" "$ours/raytracer.cpp" "$ours/scenes.cpp" "$student/"
run ~/my-cgfs
check "a faithful copy passes" test $status -eq 0
check "every test of chapter 02 ran and passed" says "^$chapter: [0-9]+ passed, 0 failed, 0 not written yet"
cmake --build build-student/my-cgfs --target render >"$work/render.log" 2>&1
check "render writes into build-student/my-cgfs/out/" test -f "build-student/my-cgfs/out/$chapter/fig-2-11.png"
check "render leaves out/ alone" test ! -e out

echo "== half written: only CanvasToViewport and IntersectRaySphere"
awk '/^\/\/ Listing 2-4/ { exit } { print }' "$ours/raytracer.cpp" >"$student/raytracer.cpp"
rm "$student/scenes.cpp"
run ~/my-cgfs 02
check "a half-written chapter passes what is written" test $status -eq 0
check "CanvasToViewport passes" says "^  CanvasToViewport +passed"
check "IntersectRaySphere passes" says "^  IntersectRaySphere +passed"
check "TraceRay is not written yet" says "^  TraceRay +not written yet"
check "Figures is not written yet" says "^  Figures +not written yet"
check "docs/students.md shows this run" shows_example half-written

echo "== a mistake: TraceRay looks only at t1, the larger root"
cp "$ours/raytracer.cpp" "$ours/scenes.cpp" "$student/"
sed -i '/if (t_min <= t2 && t2 <= t_max && t2 < closest_t) {/,/^    }/d' "$student/raytracer.cpp"
check "the mistake is planted" bash -c '! grep -q "closest_t = t2" "$1"' _ "$student/raytracer.cpp"
run ~/my-cgfs 02
check "the mistake fails" test $status -eq 1
check "the failing function is named" says "^  TraceRay +FAILED"
check "the failure page is announced" says "^images of the failed figures: "
check "the failed check and its values are on the console" says "^        (CHECK|REQUIRE).*  is  "
check "a failed figure's numbers are on the console" says "^        FAIL: [0-9]+ of 360000 pixels differ"
check "a failed figure's first wrong pixel is on the console" \
  says "^        first differing pixel: \([0-9]+, [0-9]+\) = canvas \(-?[0-9]+, -?[0-9]+\): yours \("
check "docs/students.md shows this run" shows_example worked

echo "== the mistake fixed"
cp "$ours/raytracer.cpp" "$student/"
run ~/my-cgfs 02
check "the fixed chapter passes" test $status -eq 0
check "no failure page is announced after a pass" bash -c '! grep -q "images of the failed" "$1"' \
  _ "$work/out.txt"
check "no failure page is left behind" test ! -e build-student/my-cgfs/test-output/report.html

echo "== signatures unlike ours: TraceRay's vectors by value in the header (and .cpp);"
echo "   RenderScene defined in the .cpp with a parameter more than the header declares"
by_value='s/^Color TraceRay(const Vec3& O, const Vec3& D,/Color TraceRay(Vec3 O, Vec3 D,/'
sed -i "$by_value" "$student/raytracer.h" "$student/raytracer.cpp"
sed -i 's/^void RenderScene(const Scene& scene, Canvas& canvas) {/void RenderScene(const Scene\& scene, Canvas\& canvas, int rows) {/' \
  "$student/raytracer.cpp"
check "the header's signature is changed" grep -q "^Color TraceRay(Vec3 O, Vec3 D," "$student/raytracer.h"
check "the definition's signature is changed" grep -q "Canvas& canvas, int rows) {" "$student/raytracer.cpp"
run ~/my-cgfs 02
check "signatures unlike ours fail" test $status -eq 1
check "the header's is named at the student's line, with both signatures" \
  says "/my-cgfs/02-basic-rays/raytracer.h:[0-9]+: TraceRay written with another signature: yours \`.*TraceRay\(.*Vec3, .*Vec3, double, double, const Scene&\)\`, the tests need \`Color TraceRay\(const Vec3& O"
check "the run says why it fails" says "the run fails until they match"
check "the definition's tests say so, with both signatures" \
  says "threw: written with another signature: yours is RenderScene\(.*, int\), the tests need RenderScene\("
check "docs/students.md shows this run" shows_example signatures
cp "$ours/raytracer.h" "$ours/raytracer.cpp" "$student/"

echo "== moving on: chapter 02 copied forward as 03, its headers not updated"
cp -r "$student" ~/my-cgfs/03-light
run ~/my-cgfs 03
check "a copied-forward header unlike ours fails" test $status -eq 1
check "the missing function is named" says "^03-light: ComputeLighting is not declared in your headers"
check "the copied-forward header is named" \
  says "^03-light: your raytracer.h is your chapter 02-basic-rays's, and this chapter changes it"
check "docs/students.md shows this run" shows_example moving-on
rm -r ~/my-cgfs/03-light

echo "== a compile error in chapter 03, beside the faithful chapter 02"
mkdir ~/my-cgfs/03-light
cp "$source_dir/chapters/03-light/raytracer.h" "$source_dir/chapters/03-light/raytracer.cpp" \
  "$source_dir/chapters/03-light/scenes.cpp" ~/my-cgfs/03-light/
echo 'int broken = ;' >>~/my-cgfs/03-light/raytracer.cpp
run ~/my-cgfs
check "a compile error fails" test $status -eq 1
check "the chapter that does not compile is named" \
  says "^03-light: does not compile, so none of its tests ran"
check "its first error is given, at the student's line" \
  says "^      .*/my-cgfs/03-light/raytracer.cpp:[0-9]+:[0-9]+: error: "
check "the other chapter is tested all the same" says "^$chapter: [0-9]+ passed, 0 failed"
check "docs/students.md shows this run" shows_example compile-error
check "ctest after the failed build does not pass" \
  bash -c '! ctest --test-dir build-student/my-cgfs >/dev/null 2>&1'
run ~/my-cgfs 02
check "chapter 02 asked for alone passes: the broken 03 is not even built" test $status -eq 0
rm -r ~/my-cgfs/03-light

echo "== folders that are not a student's chapters"
mkdir -p ~/misnamed/02-basic-ray
for folder in ~/nothing-here ~/misnamed; do
  run "$folder"
  check "$folder: exit status 2" test $status -eq 2
  check "$folder: one line" test "$(wc -l <"$work/out.txt")" -eq 1
done
check "the expected names are given" says "the folder names are: 02-basic-rays, 03-light"
mkdir -p ~/wrong-name/02-basic-ray ~/wrong-name/03-light
run ~/wrong-name 02
check "a chapter asked for under another name: exit status 2" test $status -eq 2
check "it gives the name its folder needs" says "its folder must be named 02-basic-rays \(found 02-basic-ray\)"
run ~/my-cgfs/02-basic-rays
check "a chapter folder given for its parent: exit status 2" test $status -eq 2
check "it says to give the parent folder" says "is itself a chapter folder: give its parent folder"
# Paths the build tools cannot carry are refused in one line, not reported as a chapter
# that does not compile.
for name in 'with"quote' 'with$dollar' 'with;semicolon' 'with${HOME}' 'with\backslash'; do
  mkdir -p ~/"$name/02-basic-rays"
  cp "$student"/* ~/"$name/02-basic-rays/"
  run ~/"$name" 02
  check "a folder named $name: exit status 2" test $status -eq 2
  check "a folder named $name: one line" test "$(wc -l <"$work/out.txt")" -eq 1
  check "a folder named $name: it says why" says "holds a character the build cannot carry"
done

echo "== a header that includes /dev/zero"
# In the student's folder, whose build folder is built already (a new folder's first
# build took 75 of this test's 144 s, alone on the 2-core machine); put back after.
cp "$student/raytracer.h" "$work/raytracer.h.faithful"
sed -i '0,/^#include/s||#include "/dev/zero"\n#include|' "$student/raytracer.h"
CGFS_BUILD_MEMORY_KB=1048576 CGFS_BUILD_TIMEOUT=120 run ~/my-cgfs 02
cp "$work/raytracer.h.faithful" "$student/raytracer.h"
check "the compiler stops at its memory limit: exit status 1" test $status -eq 1
check "the header check says the headers do not compile" \
  says "^02-basic-rays: your headers do not compile on their own"
check "the tests' rebuild of the chapter stops at the memory limit too (not killed by the kernel)" \
  says "^      cc1plus: out of memory allocating"
check "and not that they declare functions unlike ours" \
  bash -c '! grep -q "declare book functions unlike ours" "$0"' "$work/out.txt"
check "the last line says why the run fails" \
  says "^your headers do not compile on their own \(above\): the run fails until they do$"

[ $failed -eq 0 ] && echo "PASS: the documented student path works" || exit 1
