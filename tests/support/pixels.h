// Reading back what a rasterizer drew.
#pragma once

#include <set>
#include <utility>

#include "cgfs/canvas.h"

namespace cgfs::test {

// The canvas coordinates (x, y) of every pixel that is not the white background.
inline std::set<std::pair<int, int>> DrawnPixels(const Canvas& canvas) {
  std::set<std::pair<int, int>> drawn;
  for (int x = -canvas.Width() / 2; x < canvas.Width() / 2; ++x) {
    for (int y = -canvas.Height() / 2; y < canvas.Height() / 2; ++y) {
      if (canvas.GetPixel(x, y) != Rgb8{255, 255, 255}) {
        drawn.insert({x, y});
      }
    }
  }
  return drawn;
}

}  // namespace cgfs::test
