#include "cgfs/image.h"

#include <stdexcept>
#include <utility>

namespace cgfs {

Image::Image(int width, int height, Rgb8 fill) : width_(width), height_(height) {
  if (width <= 0 || height <= 0) {
    throw std::invalid_argument("image size must be positive");
  }
  bytes_.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3);
  for (std::size_t i = 0; i < bytes_.size(); i += 3) {
    bytes_[i] = fill.r;
    bytes_[i + 1] = fill.g;
    bytes_[i + 2] = fill.b;
  }
}

Image::Image(int width, int height, std::vector<std::uint8_t> bytes)
    : width_(width), height_(height), bytes_(std::move(bytes)) {
  if (width <= 0 || height <= 0 ||
      bytes_.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3) {
    throw std::invalid_argument("image bytes do not match its size");
  }
}

Rgb8 Image::At(int column, int row) const {
  const std::size_t i = Offset(column, row);
  return {bytes_[i], bytes_[i + 1], bytes_[i + 2]};
}

}  // namespace cgfs
