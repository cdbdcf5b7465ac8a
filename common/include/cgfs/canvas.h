// The canvas of book chapter 1 ("The canvas", "Coordinate systems").
//
// Coordinates have their origin at the centre, x grows to the right and y grows
// upwards. For a Cw x Ch canvas the addressable pixels are
//   x in [-Cw/2, Cw/2 - 1] and y in [-Ch/2, Ch/2 - 1],
// so every full-canvas loop is half-open: for (x = -Cw/2; x < Cw/2; ++x).
// Sizes are even so that the centre sits between four pixels, as in the book.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "cgfs/color.h"
#include "cgfs/image.h"

namespace cgfs {

// A position in the image in memory order (column from the left, row from the top).
struct ScreenPoint {
  int column = 0;
  int row = 0;
  friend bool operator==(const ScreenPoint&, const ScreenPoint&) = default;
};

class Canvas {
 public:
  // Throws std::invalid_argument unless both sizes are even and positive.
  Canvas(int width, int height, Color background = kWhite);

  int Width() const { return image_.Width(); }
  int Height() const { return image_.Height(); }

  // Sx = Cw/2 + x, Sy = Ch/2 - y - 1 (docs/conventions.md, "The canvas": the book's
  // Ch/2 - y would put y = Ch/2 on row 0 and y = -Ch/2 outside). Empty for pixels off
  // the canvas.
  std::optional<ScreenPoint> ToScreen(int x, int y) const {
    const ScreenPoint screen{Width() / 2 + x, Height() / 2 - y - 1};
    if (!image_.Contains(screen.column, screen.row)) {
      return std::nullopt;
    }
    return screen;
  }

  // The book's only drawing primitive: clamps and rounds the colour, and
  // silently ignores pixels outside the canvas.
  void PutPixel(int x, int y, const Color& color) {
    if (const std::optional<ScreenPoint> screen = ToScreen(x, y)) {
      image_.Set(screen->column, screen->row,
                 {ToChannel(color.r), ToChannel(color.g), ToChannel(color.b)});
      if (write_counts_ != nullptr) {
        ++(*write_counts_)[static_cast<std::size_t>(screen->row) * Width() + screen->column];
      }
    }
  }

  // How often each pixel is drawn over (the rasterizer's overdraw): from here on every
  // PutPixel that lands on the canvas adds one to its pixel's entry of `counts`, row by
  // row from the top (Width() x Height() entries, or std::invalid_argument), until
  // CountWrites(nullptr). A copy of the canvas counts into the same vector.
  void CountWrites(std::vector<long>* counts);

  // What PutPixel stored at (x, y), in canvas coordinates. (x, y) must be on the canvas.
  Rgb8 GetPixel(int x, int y) const;

  const Image& GetImage() const { return image_; }

 private:
  Image image_;
  std::vector<long>* write_counts_ = nullptr;
};

}  // namespace cgfs
