// An 8-bit RGB image in memory order: row 0 at the top, column 0 at the left.
// This is what files hold; the book's centred coordinates live in Canvas.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace cgfs {

struct Rgb8 {
  std::uint8_t r = 0, g = 0, b = 0;
  friend bool operator==(const Rgb8&, const Rgb8&) = default;
};

class Image {
 public:
  Image() = default;
  Image(int width, int height, Rgb8 fill = {});
  // From bytes r, g, b, r, g, b... row by row from the top (width*height*3 of them).
  Image(int width, int height, std::vector<std::uint8_t> bytes);

  int Width() const { return width_; }
  int Height() const { return height_; }
  bool Contains(int column, int row) const {
    return column >= 0 && column < width_ && row >= 0 && row < height_;
  }
  Rgb8 At(int column, int row) const;
  void Set(int column, int row, Rgb8 value) {
    const std::size_t i = Offset(column, row);
    bytes_[i] = value.r;
    bytes_[i + 1] = value.g;
    bytes_[i + 2] = value.b;
  }

  // Bytes r, g, b, r, g, b... row by row from the top.
  const std::vector<std::uint8_t>& Bytes() const { return bytes_; }

  friend bool operator==(const Image&, const Image&) = default;

 private:
  std::size_t Offset(int column, int row) const {
    return (static_cast<std::size_t>(row) * static_cast<std::size_t>(width_) +
            static_cast<std::size_t>(column)) *
           3;
  }

  int width_ = 0;
  int height_ = 0;
  std::vector<std::uint8_t> bytes_;
};

}  // namespace cgfs
