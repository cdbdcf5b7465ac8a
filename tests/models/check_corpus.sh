#!/usr/bin/env bash
# The deep checks' `models` part: every OBJ file of Debian's assimp-testmodels (models
# no one here wrote: the Wuson and the spider, concave polygons, UTF-16, long lines, no
# final newline, point clouds, empty materials, malformed ones) through --model in
# chapters 12, 14 and 5, as BUILD built them (the sanitizer build: any report fails).
# Each file either draws, with as many triangles as tinyobjloader's own Python binding
# counts (those without an area left out, and said; for polygons of more than four
# corners, which the two split differently, as many as its faces make, those
# tinyobjloader could not make said), or is refused in one line; which are refused, and
# why, must be the list in docs/testing.md. Two of them are golden images
# (tests/models/golden/), and the spider is shown in chapter 14's window, as the README
# shows it. Usage:
#   check_corpus.sh REPOSITORY BUILD [CORPUS]   (CORPUS: /usr/share/assimp/models/OBJ)
set -u
repo=$1 build=$2 corpus=${3:-/usr/share/assimp/models/OBJ}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}
[ -d "$corpus" ] || { echo "FAIL: no $corpus: install assimp-testmodels (scripts/setup --deep)"; exit 1; }
/usr/bin/python3 -c 'import tinyobjloader' 2>/dev/null ||
  { echo "FAIL: no python3-tinyobjloader (scripts/setup --deep)"; exit 1; }

# Triangles as tinyobjloader's Python binding reads the file (-1: it refuses it).
python_count() {
  /usr/bin/python3 - "$1" <<'PYTHON'
import sys, tinyobjloader
reader = tinyobjloader.ObjReader()
if not reader.ParseFromFile(sys.argv[1]):
    print(-1)
else:
    print(sum(len(shape.mesh.indices) // 3 for shape in reader.GetShapes()))
PYTHON
}

# Triangles the file's polygons make, counted apart from any OBJ reader: n - 2 for each
# face of n >= 3 corners; and its largest polygon's corners.
text_count() {
  awk '{ sub(/\r$/, "") } $1 == "f" && NF >= 4 { sum += NF - 3; if (NF - 1 > most) most = NF - 1 }
       END { print sum + 0, most + 0 }' "$1"
}

refused=$work/refused.md
for file in "$corpus"/*.obj; do
  name=$(basename "$file")
  python=$(python_count "$file")
  read -r text most < <(text_count "$file")
  reasons=""
  for chapter in 12-hidden-surface-removal 14-textures 05-raytracer-extensions; do
    timeout 120 "$build/$chapter" --model "$file" --size 200x200 --output "$work/$chapter-$name" \
      >"$work/stdout" 2>"$work/stderr"
    status=$?
    if grep -qE "ERROR: (Address|Undefined|Leak)Sanitizer|runtime error:" "$work/stderr"; then
      fail "$chapter $name: a sanitizer report"
      cat "$work/stderr"
    elif [ $status -eq 0 ]; then
      drawn=$(sed -n 's/.*, \([0-9]*\) triangles.*/\1/p' "$work/stdout" | head -n 1)
      no_area=$(sed -n 's/.*: \([0-9]*\) triangles\? without an area left out.*/\1/p' "$work/stderr")
      unsplit=$(sed -n 's/.*triangles they make: \([0-9]*\) not drawn.*/\1/p' "$work/stderr")
      said="$drawn drawn, ${no_area:-0} without an area, ${unsplit:-0} not made"
      # Polygons of more than four corners: tinyobjloader's C library and its Python
      # binding split them differently (see docs/testing.md); the text's count holds.
      if [ "$((drawn + ${no_area:-0} + ${unsplit:-0}))" -ne "$text" ]; then
        fail "$chapter $name: $said; its faces make $text"
      elif [ "$most" -le 4 ] && [ "$((drawn + ${no_area:-0}))" -ne "$python" ]; then
        fail "$chapter $name: $said; tinyobjloader's Python binding counts $python"
      else
        echo "ok: $chapter $name: $said (its faces make $text; the Python binding: $python)"
      fi
    elif [ $status -eq 2 ] && [ "$(wc -l <"$work/stderr")" -eq 1 ]; then
      reason=$(sed -e "s/^$chapter: error: //" -e "s|'$file'|the file|" "$work/stderr")
      echo "ok: $chapter $name: refused: $reason"
      reasons=$reason
    else
      fail "$chapter $name: exit status $status"
      cat "$work/stderr"
    fi
  done
  [ -n "$reasons" ] && echo "| \`$name\` | $reasons |" >>"$refused"
done

# The refused files and their reasons, as docs/testing.md lists them.
sed -n '/<!-- refused models: begin -->/,/<!-- refused models: end -->/p' "$repo/docs/testing.md" |
  grep '^| `' >"$work/documented.md"
if diff "$work/documented.md" "$refused" >"$work/diff"; then
  echo "ok: docs/testing.md lists the $(wc -l <"$refused") refused files and their reasons"
else
  fail "docs/testing.md's refused models differ from what the programs say (< docs, > now):"
  cat "$work/diff"
fi

# Golden images: the spider textured (chapter 14) and the Wuson traced (chapter 5).
for golden in "14-textures spider model" "05-raytracer-extensions WusonOBJ model"; do
  set -- $golden
  "$build/$1" --model "$corpus/$2.obj" --size 300x300 --figure "$3" --view 2.2,0.5,1.2,51,-10 \
    --output "$work/golden" >/dev/null 2>&1
  if "$repo/build/tools/cgfs-compare" "$repo/tests/models/golden/$1-$2.png" \
    "$work/golden/$3.png" --diff "$work/golden/diff.png" >"$work/compare" 2>&1; then
    echo "ok: $1 $2 equals tests/models/golden/$1-$2.png"
  else
    fail "$1 $2 differs from tests/models/golden/$1-$2.png: $(cat "$work/compare")"
  fi
done

# The README's command, 14-textures --model .../spider.obj --window, as a person uses it
# (tests/window/check_window.sh: S, then Right and S, save what the program draws).
if CGFS_WINDOW_MODEL="$corpus/spider.obj" bash "$repo/tests/window/check_window.sh" \
  "$build/14-textures" "$repo/tests/golden/14-textures" "$work/window" >"$work/window.log" 2>&1; then
  grep -E "^(ok: --model|SKIPPED)" "$work/window.log"
else
  fail "14-textures --model spider.obj --window: $(grep -E "^FAIL" "$work/window.log" | tr '\n' ' ')"
fi

echo "$failures failed"
[ "$failures" -eq 0 ]
