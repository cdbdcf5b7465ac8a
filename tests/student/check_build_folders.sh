#!/usr/bin/env bash
# scripts/student-build-folder, which names the build folder scripts/test-student uses:
# each student folder a build of its own, build-student/NAME/, so that going back and
# forth between two folders rebuilds nothing; the same folder again the same build; a
# folder of the same name elsewhere, whose build that already is, build-student/NAME-
# and eight hex digits; a name with characters a path should not hold made plain.
# Usage: check_build_folders.sh SOURCE_DIR WORK_DIR
set -euo pipefail
source_dir=$1 work=$2
rm -rf "$work"
mkdir -p "$work/repo/scripts"
cp "$source_dir/scripts/student-build-folder" "$work/repo/scripts/"
cd "$work/repo"
failed=0
want() {  # STUDENT_DIR EXPECTED
  local got
  got=$(scripts/student-build-folder "$1")
  if [ "$got" = "$2" ]; then echo "ok: $1 -> $got"; else echo "FAIL: $1 -> $got, not $2"; failed=1; fi
}
want /home/you/my-cgfs build-student/my-cgfs
want /home/you/cgfs-again build-student/cgfs-again
# my-cgfs's build exists: the same folder keeps it, another my-cgfs gets one of its own.
mkdir -p build-student/my-cgfs
echo "CGFS_STUDENT_DIR:PATH=/home/you/my-cgfs" >build-student/my-cgfs/CMakeCache.txt
want /home/you/my-cgfs build-student/my-cgfs
hash=$(printf '%s' /srv/class/my-cgfs | sha256sum | cut -c1-8)
want /srv/class/my-cgfs "build-student/my-cgfs-$hash"
want "/home/you/my cgfs (2)" "build-student/my_cgfs__2_"
[ $failed -eq 0 ] && echo "PASS: each student folder has a build folder of its own"
exit $failed
