// The canvas of book chapter 1 ("The canvas", "Coordinate systems").
//
// Coordinates have their origin at the centre, x grows to the right and y grows
// upwards. For a Cw x Ch canvas the addressable pixels are
//   x in [-Cw/2, Cw/2 - 1] and y in [-Ch/2, Ch/2 - 1],
// so every full-canvas loop is half-open: for (x = -Cw/2; x < Cw/2; ++x).
// Sizes are even so that the centre sits between four pixels, as in the book.
#pragma once

#include <optional>

#include "cgfs/color.h"
#include "cgfs/image.h"
#include "cgfs/screen.h"
#include "cgfs/tally.h"

namespace cgfs {

// Every PutPixel, on the canvas or off it (the views of where the work goes, and the
// test that a render loop visits each pixel once: cgfs/tally.h).
inline constexpr Counter kPixelsPut{"PutPixel calls"};

class Canvas {
 public:
  // Throws std::invalid_argument unless both sizes are even and positive.
  Canvas(int width, int height, Color background = kWhite);

  int Width() const { return image_.Width(); }
  int Height() const { return image_.Height(); }

  // Where pixel (x, y) is in the image: Sx = Cw/2 + x, Sy = Ch/2 - y - 1 (chapter 1's
  // mapping, cgfs/screen.h). Empty for pixels off the canvas.
  std::optional<ScreenPoint> ToScreen(int x, int y) const {
    return CanvasToScreen(x, y, Width(), Height());
  }
  // The inverse: the canvas point at (column, row) of the image.
  CanvasPoint ToCanvas(int column, int row) const {
    return ScreenToCanvas(column, row, Width(), Height());
  }

  // The book's only drawing primitive: clamps and rounds the colour, and
  // silently ignores pixels outside the canvas.
  void PutPixel(int x, int y, const Color& color) {
    TallyAt(kPixelsPut, x, y);
    if (const std::optional<ScreenPoint> screen = ToScreen(x, y)) {
      image_.Set(screen->column, screen->row,
                 {ToChannel(color.r), ToChannel(color.g), ToChannel(color.b)});
    }
  }

  // What PutPixel stored at (x, y), in canvas coordinates. (x, y) must be on the canvas.
  Rgb8 GetPixel(int x, int y) const;

  const Image& GetImage() const { return image_; }

 private:
  Image image_;
};

}  // namespace cgfs
