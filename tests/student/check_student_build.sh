#!/usr/bin/env bash
# Proves the student build (docs/students.md): the reference tests, built with
# CGFS_STUDENT_DIR against a student's copy of chapter 02, pass for a faithful
# copy and fail for a copy with one deliberate mistake; chapters the student
# has not written are reported as skipped.
# Usage: check_student_build.sh SOURCE_DIR WORK_DIR CMAKE CTEST
set -euo pipefail
source_dir=$1 work=$2 cmake=$3 ctest=$4
chapter=02-basic-rays

rm -rf "$work/good" "$work/bad"
mkdir -p "$work/good" "$work/bad"
cp -r "$source_dir/chapters/$chapter" "$work/good/"
cp -r "$source_dir/chapters/$chapter" "$work/bad/"

# The mistake: b = <CO,D> instead of 2<CO,D> in IntersectRaySphere.
mistake='s/const double b = 2 \* glm::dot(CO, D);/const double b = glm::dot(CO, D);/'
sed -i "$mistake" "$work/bad/$chapter/raytracer.cpp"
if cmp -s "$work/good/$chapter/raytracer.cpp" "$work/bad/$chapter/raytracer.cpp"; then
  echo "FAIL: could not plant the mistake; raytracer.cpp no longer has the expected line" >&2
  exit 1
fi

# One build folder for both: common and Catch2's main are compiled only once.
build=$work/build
run_student_tests() {  # student_dir -> ctest output in $work/ctest.log, status returned
  "$cmake" -S "$source_dir" -B "$build" -DCGFS_STUDENT_DIR="$1" >"$work/configure.log" 2>&1 \
    || { cat "$work/configure.log"; exit 1; }
  "$cmake" --build "$build" -j2 >"$work/build.log" 2>&1 \
    || { tail -30 "$work/build.log"; exit 1; }
  "$ctest" --test-dir "$build" --output-on-failure >"$work/ctest.log" 2>&1
}

echo "== an unmodified copy of $chapter"
if ! run_student_tests "$work/good"; then
  cat "$work/ctest.log"
  echo "FAIL: the reference tests failed on an unmodified copy" >&2
  exit 1
fi
grep -E 'tests passed' "$work/ctest.log"
# Every other chapter is missing from the student folder: each of them must show up
# as one skipped "not written yet" test, and nothing else may run for them.
others=$(grep -E '^ *[0-9]+/[0-9]+ Test +#' "$work/ctest.log" | grep -v " $chapter:" || true)
skipped=$(grep -c 'not written yet .*Skipped' <<<"$others" || true)
echo "chapters reported as not written yet (skipped): $skipped"
if [ "$skipped" -lt 1 ] || grep -v 'not written yet .*Skipped' <<<"$others" | grep -q .; then
  cat "$work/ctest.log"
  echo "FAIL: the chapters missing from the student folder were not all reported as skipped" >&2
  exit 1
fi

echo "== a copy with b = <CO,D> instead of 2<CO,D>"
if run_student_tests "$work/bad"; then
  cat "$work/ctest.log"
  echo "FAIL: the reference tests passed although the copy has a mistake" >&2
  exit 1
fi
grep -E 'tests passed|Failed' "$work/ctest.log" | head -20
echo "PASS: the student build passes a faithful copy and catches the mistake"
