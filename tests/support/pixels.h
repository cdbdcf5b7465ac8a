// Reading back what a rasterizer drew.
#pragma once

#include <algorithm>
#include <set>
#include <tuple>
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

// The canvas coordinates (x, y) of every pixel where two canvases of one size differ.
inline std::set<std::pair<int, int>> ChangedPixels(const Canvas& a, const Canvas& b) {
  std::set<std::pair<int, int>> changed;
  for (int x = -a.Width() / 2; x < a.Width() / 2; ++x) {
    for (int y = -a.Height() / 2; y < a.Height() / 2; ++y) {
      if (a.GetPixel(x, y) != b.GetPixel(x, y)) {
        changed.insert({x, y});
      }
    }
  }
  return changed;
}

// Row y of a pixel set: its first and last x, and how many pixels it has.
inline std::tuple<int, int, int> Row(const std::set<std::pair<int, int>>& pixels, int y) {
  int first = 1 << 30;
  int last = -(1 << 30);
  int count = 0;
  for (const auto& [x, row] : pixels) {
    if (row == y) {
      first = std::min(first, x);
      last = std::max(last, x);
      ++count;
    }
  }
  return {first, last, count};
}

}  // namespace cgfs::test
