#!/usr/bin/env bash
# cmake/NotWrittenYet.cmake on a made-up symbol table (a stand-in for nm prints it):
# stand-ins for a free function and a member function not written yet, a message
# naming both signatures for a function defined with other parameters, and none for
# what the chapter does not own (cgfs::, std::, Catch::) or does define.
# Usage: check_not_written_yet.sh NOT_WRITTEN_YET_CMAKE WORK_DIR
set -euo pipefail
script=$1 work=$2
rm -rf "$work"
mkdir -p "$work"
cat >"$work/symbols.txt" <<'SYMBOLS'
objects.o:
_Z16CanvasToViewportddRKN4cgfs6CanvasERK8Viewport U
_ZNK11DepthBuffer2AtEii U
_Z8TraceRayRKN3glm3vecILi3EdLNS_9qualifierE0EEES4_ddRK5Scene U
_Z8TraceRayRKN3glm3vecILi3EdLNS_9qualifierE0EEES4_ffRK5Scene T 0 10
_Z17IntersectRaySphereRKN3glm3vecILi3EdLNS_9qualifierE0EEES4_RK6Sphere U
_Z17IntersectRaySphereRKN3glm3vecILi3EdLNS_9qualifierE0EEES4_RK6Sphere T 0 10
_ZN4cgfs6Canvas8PutPixelEiiRKNS_5ColorE U
_ZNKSt6vectorIiSaIiEE4sizeEv U
_ZN5Catch7Section6beforeEv U
SYMBOLS
printf '#!/bin/sh\nfor last; do :; done\ncat "$last"\n' >"$work/nm"
chmod +x "$work/nm"
cmake -DNM="$work/nm" -DCXXFILT="$(command -v c++filt || true)" -DOUTPUT="$work/stand-ins.cpp" \
  -DOBJECTS="$work/symbols.txt" -P "$script"
cat "$work/stand-ins.cpp"

failed=0
has() { grep -qF -- "$1" "$work/stand-ins.cpp" || { echo "FAIL: no '$1'"; failed=1; }; }
lacks() { ! grep -qF -- "$1" "$work/stand-ins.cpp" || { echo "FAIL: '$1' should not be there"; failed=1; }; }
has 'not written yet: CanvasToViewport"'
has 'not written yet: DepthBuffer::At"'
has '__asm__("_ZNK11DepthBuffer2AtEii")'
has 'written with another signature: yours is TraceRay('
has 'float, float, Scene const&), the tests need TraceRay('
lacks 'IntersectRaySphere'
lacks 'PutPixel'
lacks 'vector'
lacks 'Catch'
[ $failed -eq 0 ] && echo "PASS: stand-ins for exactly the book functions not written as the tests need them"
exit $failed
