// How keys and the mouse move a figure's camera: the same in the window (--window) and
// on the chapter's web page (scripts/site), so that a view walked to in one is the
// view the other, and --view, draw.
#pragma once

#include "cgfs/view.h"

namespace cgfs {

// How far one key press moves the camera (scene units) or turns it (degrees).
inline constexpr double kCameraStep = 0.25;
inline constexpr double kCameraTurn = 5;
// How far dragging the mouse (left button held) turns it: degrees per pixel.
inline constexpr double kMouseTurn = 0.25;
// While the camera moves, frames are drawn smaller (PreviewSide) and stretched; the
// full one once no key has come for this many milliseconds.
inline constexpr int kSettleMilliseconds = 150;

// What a key does to the camera: Up / Down, D / A, PageUp / PageDown, Q / E, Home / End.
enum class CameraKey {
  kForward,
  kBack,
  kRight,
  kLeft,
  kUp,
  kDown,
  kTurnLeft,
  kTurnRight,
  kLookUp,
  kLookDown
};

// The view after one press of `key`.
View Moved(View view, CameraKey key);

// The view after the mouse was dragged `right` and `down` pixels.
View Dragged(View view, int right, int down);

// A side of the frames drawn while the camera moves: half of `side`, and even, as
// canvases are.
int PreviewSide(int side);

}  // namespace cgfs
