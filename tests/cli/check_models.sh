#!/usr/bin/env bash
# --model FILE.obj end to end (program/model_file.h): every chapter that takes it draws
# the house of tests/models/; files that are not models, or too large ones, get one
# line, exit status 2 and nothing written; a material library or a texture that cannot
# be read is one warning, and the model is drawn without it. Usage:
#   check_models.sh MODELS_DIR PROGRAM...   (the chapters with --model)
set -u
models=$1
shift
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
source "$(dirname "$0")/expect.sh"

fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}

# The bad files, each with what its one line must say.
bad=$work/files
mkdir -p "$bad"
square='v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n'
printf "$square"'f 1 2 9\n' >"$bad/out-of-range.obj"
printf "$square"'f 0 1 2\n' >"$bad/zero-index.obj"
printf 'v nan 0 0\n'"$square" >"$bad/nan.obj"
printf 'v 1e999 0 0\n'"$square" >"$bad/inf.obj"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\np 1 2 3\n' >"$bad/points.obj"
printf 'v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n' >"$bad/no-area.obj"
printf "$square"'usemtl \033[31mred\n' >"$bad/control.obj"
printf '\xfe\xff\0v\0 \0001\0 \0002\0 \0003' >"$bad/utf16.obj"
printf '\x89PNG\r\n\x1a\n' >"$bad/png.obj"
mkfifo "$bad/fifo.obj"
ln -s "$bad/loop.obj" "$bad/loop.obj"
truncate -s 300M "$bad/huge.obj"
cases=(
  "missing.obj|cannot read"
  ".|it is a directory"
  "fifo.obj|not a regular file"
  "/dev/zero|not a regular file"
  "loop.obj|cannot read"
  "huge.obj|is too large: more than 134217728 bytes"
  "png.obj|a control character"
  "utf16.obj|a NUL byte: not a text OBJ file (UTF-16 is not read)"
  "out-of-range.obj|a face refers to vertex 9 of 4"
  "zero-index.obj|'0' has an index 0 (OBJ counts from 1)"
  "nan.obj|'nan' is not a number"
  "inf.obj|not a finite number"
  "points.obj|has no faces (points and lines are not drawn)"
  "no-area.obj|has no triangle with an area"
  "control.obj|a control character"
)

for program in "$@"; do
  name=$(basename "$program")
  expect 0 "$name: draws the house" "$program" --model "$models/house.obj" --size 40x40 \
    --output "$work/$name"
  [ -s "$work/$name/model.png" ] || fail "$name: no model.png"
  grep -q "house.obj, 28 triangles" "$work/stdout" ||
    fail "$name: the caption does not say 28 triangles: $(cat "$work/stdout")"
  [ -s "$work/stderr" ] && fail "$name: a warning for the house: $(cat "$work/stderr")"
  for case in "${cases[@]}"; do
    file=${case%%|*} says=${case#*|}
    [ "${file:0:1}" = / ] || file=$bad/$file
    # (20 s cuts a hang: each is refused in well under a second quiet)
    expect 2 "$name: $(basename "$file")" timeout 20 "$program" --model "$file" --size 40x40 \
      --output "$work/bad"
    grep -qF -- "$says" "$work/stderr" || fail "$name: $(basename "$file") does not say '$says'"
  done
  [ -e "$work/bad" ] && fail "$name: something was written for a bad model" && rm -rf "$work/bad"
done

# Too many triangles for the machine: refused by counting lines, before any is parsed.
first=$1
{ printf "$square"; yes 'f 1 2 3' | head -n 4000001; } >"$bad/many.obj"
expect 2 "4 000 001 triangles" "$first" --model "$bad/many.obj" --output "$work/bad"
grep -qF "too large a model: 4 vertices and 4000003 triangles (at most" "$work/stderr" ||
  fail "4 000 001 triangles: $(cat "$work/stderr")"

# What cannot be read of a model's materials is one warning; the model is drawn.
house=$work/house
mkdir -p "$house"
sed 's/^mtllib house.mtl/mtllib missing.mtl/' "$models/house.obj" >"$house/no-library.obj"
cp "$models/house.obj" "$models/house.mtl" "$house/"  # house-bricks.ppm left behind
for program in "$@"; do
  name=$(basename "$program")
  expect 0 "$name: a missing material library" "$program" --model "$house/no-library.obj" \
    --size 40x40 --output "$work/warned"
  [ "$(wc -l <"$work/stderr")" -eq 1 ] && grep -q "warning: .*missing.mtl.*drawn without its materials" \
    "$work/stderr" || fail "$name: a missing material library: $(cat "$work/stderr")"
  if [ "${name:0:2}" = 14 ] || [ "${name:0:2}" = 15 ]; then
    expect 0 "$name: a missing texture" "$program" --model "$house/house.obj" --size 40x40 \
      --output "$work/warned"
    grep -q "warning: .*material walls: cannot read .*house-bricks.ppm.*drawn in its colour" \
      "$work/stderr" || fail "$name: a missing texture: $(cat "$work/stderr")"
  fi
done

echo "$failures failed"
[ "$failures" -eq 0 ]
