#!/usr/bin/env bash
# End-to-end checks of the command lines: exit statuses, one-line errors, and no
# file written on bad input. Usage:
#   check_command_lines.sh CHAPTER_PROGRAM CGFS_COMPARE [CHAPTER_5_PROGRAM [CHAPTER_14_PROGRAM
#     [CHAPTER_16_PROGRAM]]]
set -u
program=$1 compare=$2 chapter5=${3:-} chapter14=${4:-} chapter16=${5:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

source "$(dirname "$0")/expect.sh"

figures=$work/figures
expect 0 "renders one figure" "$program" --output "$figures" --figure fig-2-11
expect 0 "renders PPM" "$program" --output "$figures" --figure fig-2-11 --format ppm
expect 0 "renders a small canvas" "$program" --output "$work/small" --size 300x200 --figure fig-2-11
expect 0 "--help" "$program" --help
expect 0 "--list" "$program" --list

# Progress is shown only on a terminal: a render into a file or a pipe writes
# nothing to standard error.
"$program" --output "$work/quiet" --figure fig-2-11 >/dev/null 2>"$work/quiet.err"
if [ -s "$work/quiet.err" ]; then
  echo "FAIL: a render wrote to standard error when it is not a terminal:"
  cat "$work/quiet.err"
  failures=$((failures + 1))
else
  echo "ok: nothing on standard error when it is not a terminal"
fi

# Chapter 5's own options (chapters/05-raytracer-extensions/options.h).
if [ -n "$chapter5" ]; then
  expect 0 "chapter 5: --optimizations none --threads 1" "$chapter5" --output "$work/ch5" \
    --size 40x40 --figure thin-wires --optimizations none --threads 1
  expect 0 "chapter 5: a list of optimisations" "$chapter5" --output "$work/ch5" \
    --size 40x40 --figure thin-wires --optimizations bvh,threads,subsampling --threads 3
  expect 2 "chapter 5: unknown optimisation" "$chapter5" --optimizations bvh,fast --output "$work/bad"
  expect 2 "chapter 5: empty list" "$chapter5" --optimizations "" --output "$work/bad"
  expect 2 "chapter 5: zero threads" "$chapter5" --threads 0 --output "$work/bad"
  expect 2 "chapter 5: threads not a number" "$chapter5" --threads many --output "$work/bad"
  expect 2 "chapter 5: --threads 4 without threads" "$chapter5" --threads 4 \
    --optimizations cache --output "$work/bad"
fi

# Chapter 14's --texture (chapters/14-textures/options.h): any PNG, JPEG or PPM.
if [ -n "$chapter14" ]; then
  "$program" --output "$work/texture" --figure fig-2-11 --size 64x64 >/dev/null
  expect 0 "chapter 14: --texture with a PNG" "$chapter14" --output "$work/ch14" \
    --size 60x60 --figure fig-14-5-perspective-correct --texture "$work/texture/fig-2-11.png"
  "$chapter14" --output "$work/ch14-ours" --size 60x60 --figure fig-14-5-perspective-correct \
    >/dev/null
  if cmp -s "$work/ch14/fig-14-5-perspective-correct.png" \
    "$work/ch14-ours/fig-14-5-perspective-correct.png"; then
    echo "FAIL: chapter 14: --texture changed nothing"
    failures=$((failures + 1))
  else
    echo "ok: chapter 14: --texture paints the crates with the given image"
  fi
  printf 'not an image' >"$work/texture.png"
  expect 2 "chapter 14: --texture that is not an image" "$chapter14" \
    --texture "$work/texture.png" --output "$work/bad"
  expect 2 "chapter 14: --texture that does not exist" "$chapter14" \
    --texture "$work/missing.png" --output "$work/bad"
  expect 2 "chapter 14: --texture that is a folder" "$chapter14" --texture "$work" \
    --output "$work/bad"
  # A file that says it is empty but is not (/proc) is read to its end: its own error.
  expect 2 "chapter 14: /proc/self/mem as --texture" "$chapter14" --texture /proc/self/mem \
    --output "$work/bad"
  grep -q "Input/output error" "$work/stderr" ||
    { echo "FAIL: /proc/self/mem: $(cat "$work/stderr")"; failures=$((failures + 1)); }
  "$program" --output "$work/wide" --figure fig-2-11 --size 2100x8 >/dev/null
  expect 2 "chapter 14: --texture too large" "$chapter14" \
    --texture "$work/wide/fig-2-11.png" --output "$work/bad"
fi

# The business card's own options (chapters/16-business-card/options.h), and its
# size: 512x512 unless --size says otherwise.
if [ -n "$chapter16" ]; then
  expect 0 "chapter 16: --samples 2 --seed 7, plain" "$chapter16" --output "$work/ch16" \
    --size 32x32 --figure business-card --samples 2 --seed 7 --optimizations none
  expect 0 "chapter 16: the same with threads and the bound" "$chapter16" --output "$work/ch16-all" \
    --size 32x32 --figure business-card --samples 2 --seed 7 --optimizations threads,bound \
    --threads 3
  if cmp -s "$work/ch16/business-card.png" "$work/ch16-all/business-card.png"; then
    echo "ok: chapter 16: the optimisations change no pixel"
  else
    echo "FAIL: chapter 16: the optimisations changed the image"
    failures=$((failures + 1))
  fi
  if "$chapter16" --help | grep -q -- "--size WxH.*(default 512x512)"; then
    echo "ok: chapter 16: --help gives the card's size as the default"
  else
    echo "FAIL: chapter 16: --help does not give 512x512 as the default size"
    failures=$((failures + 1))
  fi
  "$chapter16" --output "$work/ch16-size" --figure business-card-1-sample >"$work/ch16-size.txt"
  if grep -q "(512x512, rendered" "$work/ch16-size.txt"; then
    echo "ok: chapter 16: 512x512 without --size"
  else
    echo "FAIL: chapter 16: not 512x512 without --size: $(cat "$work/ch16-size.txt")"
    failures=$((failures + 1))
  fi
  # Views as far as --view allows: the floor far away (its tiles' parity once went
  # through an int), in every direction (the sanitizer build checks float-to-int casts).
  expect 0 "chapter 16: a view a million units away" "$chapter16" --output "$work/ch16-far" \
    --size 8x8 --figure business-card-1-sample --view 1e6,1e6,1e6,0,0
  expect 0 "chapter 16: a view a million units the other way, looking down" "$chapter16" \
    --output "$work/ch16-far" --size 8x8 --figure business-card-1-sample \
    --view -1e6,-1e6,1e6,45,-60
  expect 2 "chapter 16: a view past a million units" "$chapter16" --output "$work/bad" \
    --size 8x8 --figure business-card-1-sample --view 1e9,0,0,0,0
  grep -qF "'1e9,0,0,0,0': x is out of range (at most 1e6 either way)" "$work/stderr" ||
    { echo "FAIL: a view out of range is not said to be"; failures=$((failures + 1)); }
  expect 2 "chapter 16: zero samples" "$chapter16" --samples 0 --output "$work/bad"
  expect 2 "chapter 16: too many samples" "$chapter16" --samples 5000 --output "$work/bad"
  expect 2 "chapter 16: samples not a number" "$chapter16" --samples lots --output "$work/bad"
  expect 2 "chapter 16: a negative seed" "$chapter16" --seed -1 --output "$work/bad"
  expect 2 "chapter 16: a seed too large" "$chapter16" --seed 99999999999 --output "$work/bad"
  expect 2 "chapter 16: unknown optimisation" "$chapter16" --optimizations bvh --output "$work/bad"
fi

expect 2 "unknown option" "$program" --colour red --output "$work/bad"
expect 2 "odd size" "$program" --size 601x600 --output "$work/bad"
expect 2 "size out of range" "$program" --size 8192x8192 --output "$work/bad"
expect 2 "size that is not a number" "$program" --size axb --output "$work/bad"
expect 2 "missing value" "$program" --output
expect 2 "unknown figure" "$program" --figure fig-99 --output "$work/bad"
expect 2 "unknown format" "$program" --format jpeg --output "$work/bad"
expect 2 "output folder is a file" "$program" --output "$figures/fig-2-11.png"
if [ -e "$work/bad" ]; then
  echo "FAIL: something was written although the arguments were bad"
  failures=$((failures + 1))
fi
if ! cmp -s "$figures/fig-2-11.png" <("$program" --output "$work/again" --figure fig-2-11 >/dev/null &&
                                       cat "$work/again/fig-2-11.png"); then
  echo "FAIL: the figure was damaged by the failed run that tried to write into it"
  failures=$((failures + 1))
fi

expect 0 "compare: a figure with itself (PNG)" "$compare" 02-basic-rays/fig-2-11 "$figures/fig-2-11.png"
expect 0 "compare: a figure with itself (PPM)" "$compare" 02-basic-rays/fig-2-11 "$figures/fig-2-11.ppm"
expect 1 "compare: a different figure" "$compare" 02-basic-rays/fig-2-11-with-ground "$figures/fig-2-11.png"
[ -f "$figures/fig-2-11.diff.png" ] || { echo "FAIL: no difference image written"; failures=$((failures + 1)); }
expect 2 "compare: unknown figure" "$compare" 02-basic-rays/fig-99 "$figures/fig-2-11.png"
expect 2 "compare: unknown chapter" "$compare" 99-nothing/fig-1 "$figures/fig-2-11.png"
expect 2 "compare: a figure without its chapter" "$compare" fig-2-11 "$figures/fig-2-11.png"
grep -qF "(a figure is CHAPTER/FIGURE: did you mean 02-basic-rays/fig-2-11?)" "$work/stderr" ||
  { echo "FAIL: a figure without its chapter is not told the name it needs"; failures=$((failures + 1)); }
expect 2 "compare: a figure's name misspelt" "$compare" 02-basic-rays/fig-2-1 "$figures/fig-2-11.png"
grep -qF "(did you mean 02-basic-rays/fig-2-11?)" "$work/stderr" ||
  { echo "FAIL: a misspelt figure is not told the name it probably meant"; failures=$((failures + 1)); }
expect 2 "compare: missing image" "$compare" 02-basic-rays/fig-2-11 "$work/missing.png"
expect 2 "compare: wrong size" "$compare" 02-basic-rays/fig-2-11 "$work/small/fig-2-11.png"
echo "not an image" >"$work/text.png"
expect 2 "compare: not an image" "$compare" 02-basic-rays/fig-2-11 "$work/text.png"
expect 2 "compare: one argument" "$compare" 02-basic-rays/fig-2-11

# Hostile inputs: each one line and exit 2, within 20 s and 2 GB of address space,
# and nothing of the user's overwritten. (20 s cuts a hang: each is refused in well
# under a second quiet, a margin of a hundred times for a busy machine, and of more
# than ten in the sanitizer build.)
# Under AddressSanitizer (CGFS_SANITIZED, the sanitize preset) the address-space limit
# is left out: the sanitizer reserves terabytes of shadow memory up front.
limit=(prlimit --as=2000000000 --)
if [ -n "${CGFS_SANITIZED:-}" ]; then
  limit=()
fi
hostile() {
  local what=$1
  shift
  expect 2 "hostile: $what" timeout 20 "${limit[@]}" "$compare" "$@"
}
good=$figures/fig-2-11.png
ln -sfn "$work/loop-b" "$work/loop-a"
ln -sfn "$work/loop-a" "$work/loop-b"
hostile "a symbolic-link loop as EXPECTED" "$work/loop-a" "$good"
hostile "a symbolic-link loop as ACTUAL" 02-basic-rays/fig-2-11 "$work/loop-a"
hostile "a symbolic-link loop as --golden" --golden "$work/loop-a" 02-basic-rays/fig-2-11 "$good"
mkdir -p "$work/locked" && cp "$good" "$work/locked/image.png" && chmod 000 "$work/locked"
as_user=()  # root reads every folder: drop to nobody for these two
if [ "$(id -u)" -eq 0 ]; then
  as_user=(setpriv --reuid=nobody --regid=nogroup --clear-groups)
fi
expect 2 "hostile: a file in an unreadable folder as EXPECTED" timeout 20 "${as_user[@]}" \
  "$compare" "$work/locked/image.png" "$good"
expect 2 "hostile: an unreadable folder as --golden" timeout 20 "${as_user[@]}" "$compare" \
  --golden "$work/locked" 02-basic-rays/fig-2-11 "$good"
expect 2 "hostile: a file in an unreadable folder as ACTUAL" timeout 20 "${as_user[@]}" "$compare" \
  02-basic-rays/fig-2-11 "$work/locked/image.png"
chmod 700 "$work/locked"
printf 'P3 32768 32768 255\n' >"$work/huge.ppm"
hostile "a P3 header declaring 32768x32768" 02-basic-rays/fig-2-11 "$work/huge.ppm"
printf 'P6 4096 4096 255\n' >"$work/short.ppm"
hostile "a P6 header declaring 4096x4096 with no pixels" 02-basic-rays/fig-2-11 "$work/short.ppm"
printf 'P3 4096 4096 255\n1 2 3\n' >"$work/short-p3.ppm"
hostile "a P3 header declaring 4096x4096 with one pixel" 02-basic-rays/fig-2-11 "$work/short-p3.ppm"
hostile "/dev/zero" 02-basic-rays/fig-2-11 /dev/zero
mkfifo "$work/fifo"
hostile "a FIFO" 02-basic-rays/fig-2-11 "$work/fifo"
hostile "a folder" 02-basic-rays/fig-2-11 "$work"
# A JPEG is read, with a note that its compression changes pixels; the note goes by
# the file's first bytes, not its name. Its JPEG comes from the fuzz seeds' writer.
seeds=$(dirname "$compare")/fuzz-seeds
if [ -x "$seeds" ]; then
  "$seeds" "$work/seeds" >/dev/null
  expect 0 "a JPEG as ACTUAL" "$compare" "$work/seeds/small.jpg" "$work/seeds/small.jpg"
  grep -qF "note: ACTUAL is a JPEG" "$work/stdout" ||
    { echo "FAIL: no note that a JPEG is lossy"; failures=$((failures + 1)); }
  cp "$good" "$work/named.jpg"
  expect 0 "a PNG named .jpg as ACTUAL" "$compare" 02-basic-rays/fig-2-11 "$work/named.jpg"
  ! grep -qF "JPEG" "$work/stdout" ||
    { echo "FAIL: a PNG named .jpg was called a JPEG"; failures=$((failures + 1)); }
fi
mkdir -p "$work/misnamed/02-basic-ray"
expect 2 "--report on a folder whose only chapter folder is misnamed" "$compare" --report "$work/misnamed"
grep -qF "did you mean 02-basic-rays?" "$work/stderr" ||
  { echo "FAIL: the misnamed chapter folder is not named with its fix"; failures=$((failures + 1)); }
# A PNG that declares 10000x10000 pixels: a decompression bomb, refused from its header.
printf '\x89PNG\r\n\x1a\n\x00\x00\x00\x0dIHDR\x00\x00\x27\x10\x00\x00\x27\x10\x08\x02\x00\x00\x00\x00\x00\x00\x00' \
  >"$work/bomb.png"
hostile "a PNG declaring 10000x10000 pixels" 02-basic-rays/fig-2-11 "$work/bomb.png"
cp "$good" "$work/keep.png"
hostile "--diff onto the image being compared" 02-basic-rays/fig-2-11 "$work/keep.png" --diff "$work/keep.png"
cmp -s "$good" "$work/keep.png" || { echo "FAIL: the user's image was changed"; failures=$((failures + 1)); }
# Nothing the run reads is written over: a student's image as --html, an image of the
# folder that is not one of our figures, a golden image as --diff (a copy of ours).
mkdir -p "$work/inputs/02-basic-rays" "$work/inputs/03-light" "$work/golden-copy"
cp "$good" "$work/inputs/02-basic-rays/fig-2-11.png"
cp "$good" "$work/inputs/03-light/fig-3-16.png"
"$program" --output "$work/golden-copy/02-basic-rays" >/dev/null
expect 2 "--html onto a student's image in the folder" "$compare" --report "$work/inputs" \
  --html "$work/inputs/02-basic-rays/fig-2-11.png"
expect 2 "--html onto an image of the folder that is not one of ours" "$compare" \
  --report "$work/inputs" --html "$work/inputs/03-light/fig-3-16.png"
expect 2 "--diff onto a golden image" "$compare" --golden "$work/golden-copy" \
  02-basic-rays/fig-2-11 "$good" --diff "$work/golden-copy/02-basic-rays/fig-2-11-with-ground.png"
if ! cmp -s "$good" "$work/inputs/02-basic-rays/fig-2-11.png" ||
  ! cmp -s "$good" "$work/inputs/03-light/fig-3-16.png" ||
  ! "$compare" 02-basic-rays/fig-2-11-with-ground \
    "$work/golden-copy/02-basic-rays/fig-2-11-with-ground.png" --diff "$work/gd.png" >/dev/null; then
  echo "FAIL: an image the run reads was written over"
  failures=$((failures + 1))
fi
expect 1 "--html beside the folder's images, not over one" "$compare" --report "$work/inputs" \
  --html "$work/inputs/02-basic-rays/page.html"
# A golden image reached through a bind mount of another folder (bubblewrap makes one)
# is still that image: refused by device and inode, for --html and --diff alike.
if command -v bwrap >/dev/null && bwrap --ro-bind / / --unshare-all true 2>/dev/null; then
  mkdir -p "$work/mounted"
  mounted() {  # COMPARE ARGUMENTS..., with the golden copy bound at $work/mounted
    bwrap --dev-bind / / --bind "$work/golden-copy" "$work/mounted" "$@"
  }
  expect 2 "--html onto a golden image through a bind mount" mounted "$compare" --golden "$work/golden-copy" \
    --report "$work/inputs" --html "$work/mounted/02-basic-rays/fig-2-11.png"
  expect 2 "--diff onto a golden image through a bind mount" mounted "$compare" --golden "$work/golden-copy" \
    02-basic-rays/fig-2-11 "$good" --diff "$work/mounted/02-basic-rays/fig-2-11-with-ground.png"
  "$program" --output "$work/golden-again" >/dev/null
  if ! cmp -s "$work/golden-again/fig-2-11.png" "$work/golden-copy/02-basic-rays/fig-2-11.png" ||
    ! cmp -s "$work/golden-again/fig-2-11-with-ground.png" "$work/golden-copy/02-basic-rays/fig-2-11-with-ground.png"; then
    echo "FAIL: a golden image was written over through a bind mount"
    failures=$((failures + 1))
  fi
fi
# Names as long as a file name may be (255 bytes) are written; the temporary beside
# them has a name that fits too.
long=$(printf 'a%.0s' $(seq 1 240))
expect 0 "--diff with a 244-byte name" "$compare" 02-basic-rays/fig-2-11 "$good" \
  --diff "$work/$long.png"
expect 0 "--diff with a 255-byte name" "$compare" 02-basic-rays/fig-2-11 "$good" \
  --diff "$work/${long}aaaaaaaaaaa.png"
# An error that echoes a value with a newline or another control character in it is
# still one line.
expect 2 "--size with a newline in it" "$program" --size $'600\nx600' --output "$work/bad"
expect 2 "--figure with a newline and an escape in it" "$program" --figure $'fig\n\e[2J' \
  --output "$work/bad"
expect 2 "an image whose name has a newline in it" "$compare" 02-basic-rays/fig-2-11 \
  "$work/no"$'\n'"such.png"

# Files are written safely (program/include/program/safe_file.h): never over something that
# is not a regular file, never through what stands at a temporary's name, whole or not
# at all, and nothing left behind.
safe=$work/safe
mkdir -p "$safe/student/02-basic-rays"
cp "$good" "$safe/student/02-basic-rays/fig-2-11.png"
# A stand-in for a device node, made in the scratch folder (never a real one); as a
# user that may not make device nodes, a FIFO stands in for it.
if mknod "$safe/node" c 1 3 2>/dev/null; then node_kind=device; else mkfifo "$safe/node"; node_kind=FIFO; fi
node_before=$(stat -c '%F %t:%T' "$safe/node")
expect 2 "a $node_kind as --diff" timeout 20 "$compare" 02-basic-rays/fig-2-11 "$good" --diff "$safe/node"
expect 2 "a $node_kind as --html" timeout 20 "$compare" --report "$safe/student" --html "$safe/node"
mkdir -p "$safe/out"
if mknod "$safe/out/fig-2-11.png" c 1 3 2>/dev/null; then :; else mkfifo "$safe/out/fig-2-11.png"; fi
expect 2 "a $node_kind where a figure goes" timeout 20 "$program" --figure fig-2-11 --size 16x16 \
  --output "$safe/out"
if [ "$(stat -c '%F %t:%T' "$safe/node")" != "$node_before" ] || [ -f "$safe/out/fig-2-11.png" ]; then
  echo "FAIL: a $node_kind was replaced by a file"
  failures=$((failures + 1))
fi
mkfifo "$safe/fifo.png"
expect 2 "a FIFO as --diff, without waiting" timeout 20 "$compare" 02-basic-rays/fig-2-11 "$good" \
  --diff "$safe/fifo.png"
# What stands at the old fixed temporary names is never written through or waited on.
mkdir -p "$safe/planted"
echo precious >"$safe/victim.txt"
ln -s ../victim.txt "$safe/planted/fig-2-11.png.partial"
mkfifo "$safe/planted/fig-2-11-with-ground.png.partial"
expect 0 "a symbolic link and a FIFO at the old temporaries' names" timeout 20 "$program" \
  --size 16x16 --output "$safe/planted"
if [ "$(cat "$safe/victim.txt")" != precious ] || [ ! -L "$safe/planted/fig-2-11.png.partial" ]; then
  echo "FAIL: a file was written through a symbolic link"
  failures=$((failures + 1))
fi
leftovers() { find "$1" -name '.*.partial' | wc -l; }
# Two renders into one folder at once: each writes a whole file and says so, and the
# file is one of the two, whole.
if [ -n "$chapter16" ]; then
  "$chapter16" --figure business-card --size 64x64 --samples 2 --seed 1 --output "$safe/seed1" >/dev/null
  "$chapter16" --figure business-card --size 64x64 --samples 2 --seed 2 --output "$safe/seed2" >/dev/null
  races=0
  for attempt in 1 2 3 4 5 6 7 8; do
    "$chapter16" --figure business-card --size 64x64 --samples 2 --seed 1 --output "$safe/race" \
      >"$safe/one.out" 2>&1 &
    first=$!
    "$chapter16" --figure business-card --size 64x64 --samples 2 --seed 2 --output "$safe/race" \
      >"$safe/two.out" 2>&1
    second=$?
    wait $first
    first=$?
    card=$safe/race/business-card.png
    if [ $first -ne 0 ] || [ $second -ne 0 ] || ! grep -q '^wrote' "$safe/one.out" ||
      ! grep -q '^wrote' "$safe/two.out" ||
      ! { cmp -s "$card" "$safe/seed1/business-card.png" ||
        cmp -s "$card" "$safe/seed2/business-card.png"; } || [ "$(leftovers "$safe/race")" -ne 0 ]; then
      races=$((races + 1))
    fi
  done
  if [ $races -ne 0 ]; then
    echo "FAIL: two renders into one folder went wrong in $races of 8 tries"
    failures=$((failures + 1))
  else
    echo "ok: two renders into one folder at once, 8 times: both wrote, the file is one of theirs"
  fi
fi
# SIGTERM while the file is being written (sent as soon as its temporary appears), and
# while it is being drawn: no temporary left, and the destination the old file or the
# whole new one.
mkdir -p "$safe/term"
"$program" --figure fig-2-11 --size 64x64 --format ppm --output "$safe/term" >/dev/null
cp "$safe/term/fig-2-11.ppm" "$safe/old.ppm"
# The same with SIGHUP, the terminal closed. (SIGINT cannot be tried here: a shell
# without job control starts its background programs with SIGINT ignored.)
caught=0
for attempt in 1 2 3 4 5 6; do
  signal=TERM
  [ $((attempt % 2)) -eq 0 ] && signal=HUP
  "$program" --figure fig-2-11 --size 4096x4096 --format ppm --output "$safe/term" >/dev/null 2>&1 &
  victim=$!
  if [ $attempt -ge 5 ]; then
    sleep 0.1  # while drawing
  else
    for _ in $(seq 500); do
      [ "$(leftovers "$safe/term")" -ne 0 ] && break
      sleep 0.01
    done
  fi
  kill -$signal $victim 2>/dev/null
  wait $victim 2>/dev/null
  status=$?
  { [ $status -eq 143 ] || [ $status -eq 129 ]; } && caught=$((caught + 1))
  if [ "$(leftovers "$safe/term")" -ne 0 ]; then
    echo "FAIL: SIG$signal (try $attempt) left a temporary file behind"
    failures=$((failures + 1))
  elif ! cmp -s "$safe/term/fig-2-11.ppm" "$safe/old.ppm" &&
    ! "$compare" "$safe/term/fig-2-11.ppm" "$safe/term/fig-2-11.ppm" >/dev/null 2>&1; then
    # Neither the old file nor a whole new one (the signal may come just after the rename).
    echo "FAIL: SIG$signal (try $attempt) left the figure damaged"
    failures=$((failures + 1))
  fi
  cp "$safe/old.ppm" "$safe/term/fig-2-11.ppm"
done
echo "ok: SIGTERM and SIGHUP while writing (4 tries) and drawing: stopped $caught of 6 times, nothing half-written, nothing left"

# Threads that cannot be started (too little address space for their stacks): one line.
if [ -n "$chapter16" ] && [ -z "${CGFS_SANITIZED:-}" ]; then
  expect 2 "chapter 16: --threads 256 with 2 GB of address space" prlimit --as=2000000000 -- \
    "$chapter16" --threads 256 --samples 1 --figure business-card --output "$safe/threads"
  [ -e "$safe/threads/business-card.png" ] &&
    { echo "FAIL: a figure was written although its threads failed"; failures=$((failures + 1)); }
fi

# Write errors on standard output are errors, in every program.
expect 2 "chapter program: --list into a full disk" bash -c '"$1" --list >/dev/full' _ "$program"
expect 2 "compare: output into a full disk" bash -c '"$1" 02-basic-rays/fig-2-11 "$2" >/dev/full' \
  _ "$compare" "$good"

echo "$failures failed"
[ "$failures" -eq 0 ]
