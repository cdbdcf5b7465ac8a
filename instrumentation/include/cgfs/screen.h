// Chapter 1's mapping ("The canvas", "Coordinate systems") between a canvas point, origin
// at the centre and y growing upwards, and the image in memory, column from the left and
// row from the top: Sx = Cw/2 + x, Sy = Ch/2 - y - 1 (docs/conventions.md, "The canvas":
// the book's Ch/2 - y would put y = Ch/2 on row 0 and y = -Ch/2 outside). The one place
// it is written: the canvas (cgfs/canvas.h), the tally (cgfs/tally.h) and every buffer
// kept per pixel find a pixel through it. It lives at the ground floor, below both.
#pragma once

#include <optional>

namespace cgfs {

// A position in the image in memory order (column from the left, row from the top).
struct ScreenPoint {
  int column = 0;
  int row = 0;
  friend bool operator==(const ScreenPoint&, const ScreenPoint&) = default;
};

// A point of the canvas, in the book's coordinates.
struct CanvasPoint {
  int x = 0;
  int y = 0;
  friend bool operator==(const CanvasPoint&, const CanvasPoint&) = default;
};

// Where canvas point (x, y) of a width x height canvas is in the image; empty for a
// point off the canvas.
constexpr std::optional<ScreenPoint> CanvasToScreen(int x, int y, int width, int height) {
  const ScreenPoint screen{width / 2 + x, height / 2 - y - 1};
  if (screen.column < 0 || screen.column >= width || screen.row < 0 || screen.row >= height) {
    return std::nullopt;
  }
  return screen;
}

// The inverse: the canvas point at (column, row) of a width x height image.
constexpr CanvasPoint ScreenToCanvas(int column, int row, int width, int height) {
  return {column - width / 2, height / 2 - 1 - row};
}

}  // namespace cgfs
