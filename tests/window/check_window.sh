#!/usr/bin/env bash
# --window as a person uses it, under a virtual display (Xvfb) with keys pressed by
# xdotool: chapter 2's window opens on its first figure; S saves it, byte for byte its
# golden image; Right shows the next figure, whose saved file is its golden image too;
# Esc closes the window, exit status 0. Without a display --window says so in one
# line, exit status 2. Leaves a screenshot in WORK_DIR/window.png. Skipped without
# Xvfb and xdotool (CI installs them: scripts/setup). Then chapter 5's camera: moved
# forward and turned with the keys, the figure saved from the window is byte for byte
# what the program draws for the view the window printed (--view).
# Usage: check_window.sh CHAPTER_02_PROGRAM CHAPTER_05_PROGRAM GOLDEN_DIR WORK_DIR
set -euo pipefail
program=$1 camera_program=$2 golden=$3 work=$4
rm -rf "$work"
mkdir -p "$work"
failed=0
fail() { echo "FAIL: $*"; failed=1; }

env -u DISPLAY -u WAYLAND_DISPLAY "$program" --window --output "$work/none" >"$work/no-display.txt" 2>&1 \
  && status=0 || status=$?
cat "$work/no-display.txt"
[ $status -eq 2 ] || fail "without a display: exit status $status, expected 2"
[ "$(wc -l <"$work/no-display.txt")" -eq 1 ] || fail "without a display: more than one line"
if grep -q "needs SDL2" "$work/no-display.txt"; then
  echo "SKIPPED: this build has no SDL2 (libsdl2-dev), so no window to test"
  exit $failed
fi
if ! command -v Xvfb >/dev/null || ! command -v xdotool >/dev/null; then
  echo "SKIPPED: no Xvfb and xdotool to open and drive a window (CI installs them: scripts/setup)"
  exit $failed
fi

# A display of its own, numbered by Xvfb; stopped on the way out, with the program.
exec 3>"$work/display"
Xvfb -displayfd 3 -screen 0 800x700x24 -nolisten tcp >"$work/xvfb.log" 2>&1 &
xvfb=$!
program_pid=""
trap 'kill $program_pid $xvfb 2>/dev/null || true' EXIT
for _ in $(seq 100); do [ -s "$work/display" ] && break; sleep 0.1; done
export DISPLAY=":$(head -1 "$work/display")"
echo "virtual display $DISPLAY"

"$program" --window --output "$work/saved" >"$work/window.txt" 2>&1 &
program_pid=$!
window=$(timeout 20 xdotool search --sync --name "^02-basic-rays: " | head -1)
xdotool windowfocus --sync "$window"
saved() {  # waits until the program says it saved $1
  for _ in $(seq 100); do grep -q "saved .*/$1\( \|\$\)" "$work/window.txt" && return 0; sleep 0.1; done
  return 1
}
same_as_golden() {
  saved "$1.png" || { fail "$1.png was not saved"; return; }
  cmp -s "$work/saved/$1.png" "$golden/$1.png" && echo "ok: $1 from the window is its golden image" \
    || fail "$1 from the window differs from its golden image"
}
xdotool key s
same_as_golden fig-2-11
echo "title: $(xdotool getwindowname "$window")"
xdotool getwindowname "$window" | grep -q "^02-basic-rays: fig-2-11 - .* - [0-9.]* ms$" \
  || fail "the title does not name the figure and its time"
import -display "$DISPLAY" -window "$window" "$work/window.png" 2>/dev/null || true
xdotool key Right
xdotool key s
same_as_golden fig-2-11-with-ground
xdotool key Escape
status=0
wait $program_pid || status=$?
program_pid=""
[ $status -eq 0 ] || fail "Esc: exit status $status, expected 0"
cat "$work/window.txt"

# Chapter 5's camera, moved in the window: forward twice, turned left once.
"$camera_program" --window --figure fig-5-1-camera --output "$work/moved" >"$work/window.txt" 2>&1 &
program_pid=$!
window=$(timeout 20 xdotool search --sync --name "^05-raytracer-extensions: " | head -1)
xdotool windowfocus --sync "$window"
xdotool key Up Up q s
if saved fig-5-1-camera.png; then
  view=$(grep -o -- "--view [^)]*" "$work/window.txt" | tail -1 | cut -d' ' -f2)
  echo "the window's view: $view"
  [ "$view" = "0,0,0.5,5,0" ] || fail "the view after Up Up Q is $view, not 0,0,0.5,5,0"
  "$camera_program" --figure fig-5-1-camera --view "$view" --output "$work/drawn" >/dev/null
  cmp -s "$work/moved/fig-5-1-camera.png" "$work/drawn/fig-5-1-camera.png" \
    && echo "ok: the moved window's figure is what --view $view draws" \
    || fail "the moved window's figure differs from what --view $view draws"
  cmp -s "$work/moved/fig-5-1-camera.png" "$golden/../05-raytracer-extensions/fig-5-1-camera.png" \
    && fail "the camera did not move: the figure is the golden one"
else
  fail "the moved figure was not saved"
fi
xdotool getwindowname "$window" | grep -q " - view 0,0,0.5,5,0$" \
  || fail "the title does not show the view"
import -display "$DISPLAY" -window "$window" "$work/window-moved.png" 2>/dev/null || true
xdotool key Escape
wait $program_pid || fail "chapter 5's window did not close cleanly"
program_pid=""
cat "$work/window.txt"
[ $failed -eq 0 ] && echo "PASS: the window shows, saves and flips through the figures, and moves the camera"
exit $failed
