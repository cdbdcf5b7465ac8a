#!/usr/bin/env bash
# shellcheck disable=SC2016,SC2317  # the checks run through check(): bash -c with its own $1
# The function checker's verdict in the folder layouts students have (docs/students.md,
# "Where your code runs"): a forger (forgers/forger.py, forger.js) whose CanvasToViewport
# searches the file system for the answers gets a failed case and exit status 1 in each:
#   A  the student's folder holds another copy of the project (an older clone with its
#      history, a download, a case file copied under another name);
#   B  the python3 on PATH is a virtual environment whose folder holds the repository;
#   C  node is <dir>/bin/node and <dir> holds the repository;
#   D  the student's home is reached through a symbolic link, and holds the repository;
# and in every one, nothing of the checker's command line or environment shows in
# /proc/1. Skipped without node or bubblewrap; B without python3's venv.
# Usage: check_layouts.sh SOURCE_DIR WORK_DIR
set -euo pipefail
source_dir=$(realpath "$1") work=$2
rm -rf "$work"
mkdir -p "$work"
work=$(realpath "$work")
# shellcheck source=tests/check-functions/checks.sh
source "$(dirname "${BASH_SOURCE[0]}")/checks.sh"
if ! command -v node >/dev/null || ! bwrap --ro-bind / / --unshare-all true 2>/dev/null; then
  echo "SKIPPED: no node or no bubblewrap sandbox here (CI installs both: scripts/setup)"
  exit 0
fi
forgers=$source_dir/tests/check-functions/forgers
# A copy of the repository as the checker needs it: its code and the case files.
repository() {
  mkdir -p "$1/tools" "$1/tests"
  cp -r "$source_dir/tools/check-functions" "$1/tools/"
  cp -r "$source_dir/tests/cases" "$1/tests/"
}
# RUN CHECKER FILE [node]: the check, its output in out.txt, its status in $status.
run() {
  local checker=$1 file=$2 node=${3:-node}
  status=0
  CGFS_LAYOUT_SECRET=checker-environment "$node" "$checker/tools/check-functions/check-functions.js" 02 "$file" \
    >"$work/out.txt" 2>&1 || status=$?
  sed 's/^/    /' "$work/out.txt" | cut -c1-240
}
forged() {  # WHAT: the forger failed its case, and learnt nothing of the checker
  check "$1: exit status 1" test $status -eq 1
  check "$1: CanvasToViewport failed" says "^  CanvasToViewport +FAILED 6 of 6 cases"
  check "$1: no answer found (0 answers)" says "\(0 answers\)"
  check "$1: /proc/1 shows none of the checker's command line or environment" \
    bash -c 'grep "leaked:" "$1" | grep -q . && ! grep "leaked:" "$1" | grep -qE "check-functions\.js|CGFS_LAYOUT_SECRET|checker-environment|HOME=|PATH="' _ "$work/out.txt"
}

echo "== the forger in the project's own layout"
mkdir -p "$work/plain"
cp "$forgers/forger.py" "$forgers/forger.js" "$work/plain/"
run "$source_dir" "$work/plain/forger.py"
forged "Python, as usual"
run "$source_dir" "$work/plain/forger.js"
forged "JavaScript, as usual"

echo "== A: the student's folder holds copies of the project"
a=$work/A/home
repository "$a/cgfs-old"
mkdir -p "$a/answers" "$a/history"
cp "$source_dir/tests/cases/02-basic-rays.json" "$a/answers/"
cp "$source_dir/tests/cases/02-basic-rays.json" "$a/answers/notes.txt"
if command -v git >/dev/null; then  # a clone's history alone: the files deleted, git keeps them
  git -C "$a/history" init -q
  cp "$source_dir/tests/cases/02-basic-rays.json" "$a/history/"
  git -C "$a/history" add . && git -C "$a/history" -c user.name=s -c user.email=s@s commit -qm cases
  rm "$a/history/02-basic-rays.json"
fi
cp "$forgers/forger.py" "$forgers/forger.js" "$a/"
run "$source_dir" "$a/forger.py"
forged "A, Python"
run "$source_dir" "$a/forger.js"
forged "A, JavaScript"

echo "== B: python3 is a virtual environment that holds the repository"
if python3 -m venv --without-pip "$work/B" 2>/dev/null; then
  repository "$work/B/cgfs"
  mkdir -p "$work/B-student"
  cp "$forgers/forger.py" "$work/B-student/"
  PATH=$work/B/bin:$PATH run "$work/B/cgfs" "$work/B-student/forger.py"
  forged "B, Python"
else
  echo "skipped: B (python3 -m venv does not work here)"
fi

echo "== C: node is <dir>/bin/node, and <dir> holds the repository"
mkdir -p "$work/C/bin" "$work/C-student"
node_program=$(node -p 'require("fs").realpathSync(process.execPath)')
ln "$node_program" "$work/C/bin/node" 2>/dev/null || cp "$node_program" "$work/C/bin/node"
repository "$work/C/cgfs"
cp "$forgers/forger.js" "$work/C-student/"
run "$work/C/cgfs" "$work/C-student/forger.js" "$work/C/bin/node"
forged "C, JavaScript"

echo "== D: the home is reached through a symbolic link"
repository "$work/D-real/cgfs"
cp "$forgers/forger.py" "$forgers/forger.js" "$work/D-real/"
ln -s "$work/D-real" "$work/D-link"
run "$work/D-real/cgfs" "$work/D-link/forger.py"
forged "D, Python"
run "$work/D-real/cgfs" "$work/D-link/forger.js"
forged "D, JavaScript"
check "the report names the file as it was given" says "^02-basic-rays: forger.js"

[ $failed -eq 0 ] && echo "PASS: a forger finds no answer in any layout"
exit $failed
