#include "cgfs/canvas.h"

#include <stdexcept>
#include <string>

namespace cgfs {

namespace {

Rgb8 ToRgb8(const Color& color) {
  return {ToChannel(color.r), ToChannel(color.g), ToChannel(color.b)};
}

int CheckedSize(int size, const char* what) {
  if (size <= 0 || size % 2 != 0) {
    throw std::invalid_argument(std::string("canvas ") + what + " must be a positive even number");
  }
  return size;
}

}  // namespace

Canvas::Canvas(int width, int height, Color background)
    : image_(CheckedSize(width, "width"), CheckedSize(height, "height"), ToRgb8(background)) {}

Rgb8 Canvas::GetPixel(int x, int y) const {
  const auto screen = ToScreen(x, y);
  if (!screen) {
    throw std::out_of_range("GetPixel(" + std::to_string(x) + ", " + std::to_string(y) +
                            ") is outside the canvas");
  }
  return image_.At(screen->column, screen->row);
}

}  // namespace cgfs
