#!/usr/bin/env bash
# docs/students.md, "1. Any language: compare an image", run as written: its commands,
# in a student's folder ~/my-cgfs with this repository as ~/cgfs, on the images its
# worked examples describe (our chapter 2 figure moved one row down and written as P3,
# our figure as PNG, and a folder laid out like out/ with one figure right, one moved,
# one of another chapter and one misnamed), each example's output what the command prints.
# Usage: check_compare_examples.sh SOURCE_DIR CHAPTER_02_PROGRAM WORK_DIR
set -euo pipefail
source_dir=$1 program=$2 work=$3
rm -rf "$work"
mkdir -p "$work/home/my-cgfs" "$work/ours"
export HOME=$work/home
ln -s "$source_dir" ~/cgfs
failed=0
check() {
  local what=$1
  shift
  if "$@"; then echo "ok: $what"; else echo "FAIL: $what"; failed=1; fi
}

# The images the examples describe.
"$program" --output "$work/ours" --format ppm >/dev/null
python3 - "$work/ours/fig-2-11-with-ground.ppm" ~/my-cgfs/book-rows.ppm <<'EOF'
# Our figure one row down, its first row white (the book's Sy = Ch/2 - y), as P3.
import sys
data = open(sys.argv[1], "rb").read()
pixels = data[data.index(b"255\n") + 4:]
width = height = 600
rows = [bytes([255] * width * 3)] + [pixels[r * width * 3:(r + 1) * width * 3] for r in range(height - 1)]
with open(sys.argv[2], "w") as out:
    out.write(f"P3\n{width} {height}\n255\n" + "\n".join(" ".join(map(str, row)) for row in rows) + "\n")
EOF
cp "$source_dir/tests/golden/02-basic-rays/fig-2-11-with-ground.png" ~/my-cgfs/mine.png
mkdir -p ~/my-cgfs/my-images/02-basic-rays ~/my-cgfs/my-images/03-light
cp ~/my-cgfs/book-rows.ppm ~/my-cgfs/my-images/02-basic-rays/fig-2-11-with-ground.ppm
cp "$source_dir/tests/golden/02-basic-rays/fig-2-11.png" ~/my-cgfs/my-images/02-basic-rays/
cp "$source_dir/tests/golden/02-basic-rays/fig-2-11.png" ~/my-cgfs/my-images/03-light/fig-3-7-diffuse.png
cp "$work/ours/fig-2-11.ppm" ~/my-cgfs/my-images/03-light/fig-3-16.ppm
cp "$work/ours/fig-2-11-with-ground.ppm" ~/my-cgfs/mine.ppm

# The commands, as written.
mapfile -t commands < <(awk '/<!-- compare:/ { marked = 1 } marked && /^```sh/ { inside = 1; next }
  inside && /^```/ { exit } inside { print }' "$source_dir/docs/students.md")
check "docs/students.md gives the commands" test ${#commands[@]} -eq 2
status=0
(eval "${commands[0]}" && eval "${commands[1]}") >"$work/out.txt" 2>&1 || status=$?
check "as documented: ${commands[*]}" test $status -eq 0
check "it passes on our own figure" grep -q "^PASS: 0 of 360000 pixels" "$work/out.txt"

# Each worked example, its output.
awk -v work="$work" '/<!-- example: compare / { name = $4; next } name && /^```$/ && inside { inside = 0; name = ""; next }
  name && /^```/ { inside = 1; out = work "/example-" name; next }
  inside { print > out }' "$source_dir/docs/students.md"
for example in $(find "$work" -maxdepth 1 -name 'example-*' | sort); do
  command=$(head -1 "$example" | sed 's/^\$ //')
  (cd ~/my-cgfs && eval "$command") >"$work/out.txt" 2>&1 || true
  check "the worked example $(basename "$example"): its output is what the command prints" \
    diff <(tail -n +2 "$example" | grep -v '^\$ echo \$?$' | sed '/^[0-9]$/d') "$work/out.txt"
done
check "docs/students.md has the three worked examples" test "$(find "$work" -maxdepth 1 -name 'example-*' | wc -l)" -eq 3
[ $failed -eq 0 ] && echo "PASS: docs/students.md's comparison commands work as written"
exit $failed
