#!/usr/bin/env bash
# scripts/test-student on a student's chapter 2 whose code, as its tests start, reaches
# out of the sandbox it runs in (docs/students.md): it writes outside the build folder,
# appends to one of our golden images, reads a file of the user's outside this repository
# and its folder, and starts a process meant to outlive the run. None of it happens, and
# its tests still run and pass. Skipped without bubblewrap.
# Usage: check_student_sandbox.sh SOURCE_DIR WORK_DIR
set -euo pipefail
source_dir=$1 work=$2
rm -rf "$work"
mkdir -p "$work"
work=$(cd "$work" && pwd)
if ! command -v bwrap >/dev/null || ! bwrap --ro-bind / / --unshare-all true 2>/dev/null; then
  echo "SKIPPED: no bubblewrap sandbox here (CI installs it: scripts/setup)"
  exit 0
fi
failed=0
check() {
  local what=$1
  shift
  if "$@"; then echo "ok: $what"; else echo "FAIL: $what"; failed=1; fi
}
# The user's files: outside the repository, the student's folder and the build folder.
outside=$(mktemp -d)
trap 'rm -rf "$outside"' EXIT
echo "a secret of the user's" >"$outside/secret.txt"
marker=cgfs-outliving-$$
student=$work/my-cgfs
mkdir -p "$student/02-basic-rays"
cp "$source_dir/chapters/02-basic-rays/"*.{h,cpp} "$student/02-basic-rays/"
rm "$student/02-basic-rays/main.cpp"
golden=$source_dir/tests/golden/02-basic-rays/fig-2-11.png
cat >"$student/02-basic-rays/escape.cpp" <<EOF
// Runs as each test program starts: everything here must fail, quietly.
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>

namespace {
struct Escape {
  Escape() {
    std::ofstream("$outside/written-by-the-student") << "x";
    std::ofstream("$golden", std::ios::app) << "x";
    std::ifstream secret("$outside/secret.txt");
    const std::string read{std::istreambuf_iterator<char>(secret), std::istreambuf_iterator<char>()};
    std::ofstream("$work/build/what-the-student-read") << (read.empty() ? "nothing" : read);
    std::system("setsid sh -c 'sleep 600' $marker >/dev/null 2>&1 &");
  }
} escape;
}  // namespace
EOF
golden_before=$(md5sum "$golden")
status=0
(cd "$source_dir" && CGFS_STUDENT_BUILD="$work/build" scripts/test-student "$student" 02) >"$work/out.txt" 2>&1 || status=$?
sed 's/^/    /' "$work/out.txt"
check "its tests ran and passed" test $status -eq 0
check "it ran in the sandbox (no note says otherwise)" bash -c '! grep -q "^note: no sandbox" "$1"' _ "$work/out.txt"
check "nothing was written outside the build folder" test ! -e "$outside/written-by-the-student"
check "our golden image is as it was" test "$golden_before" = "$(md5sum "$golden")"
check "the user's file outside was not read" test ! -e "$work/build/what-the-student-read" -o \
  "$(cat "$work/build/what-the-student-read" 2>/dev/null)" = nothing
sleep 1
check "no process it started is left" test -z "$(pgrep -f "$marker" || true)"
[ $failed -eq 0 ] && echo "PASS: a student's C++ chapter stays in its sandbox"
exit $failed
