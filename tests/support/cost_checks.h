// Checks of the chapters' cost views (program/cost_view.h): that the figure draws each
// pixel's count through the ramp, and says their totals once drawn.
#pragma once

#include <catch2/catch.hpp>

#include <algorithm>
#include <numeric>
#include <string>
#include <vector>

#include "golden.h"
#include "program/cost_view.h"
#include "program/figure.h"

namespace cgfs::test {

// 1234567 as a caption writes it: "1 234 567".
inline std::string Spaced(cgfs::Count n) {
  const std::string digits = std::to_string(n);
  std::string spaced;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) {
      spaced += ' ';
    }
    spaced += digits[i];
  }
  return spaced;
}

inline cgfs::Count Total(const std::vector<cgfs::Count>& counts) {
  return std::accumulate(counts.begin(), counts.end(), cgfs::Count{0});
}

inline cgfs::Count Max(const std::vector<cgfs::Count>& counts) {
  return *std::max_element(counts.begin(), counts.end());
}

// Figure `name`, at the golden size, shows each pixel's count (row by row from the
// top) through the ramp with `scale_max` at its top, above the scale strip (a negative
// count: nothing there, kCostNothing), and says once drawn "<total> in all, at most
// <max>" of them (the negative counts left out of the total).
inline void CheckDrawn(const std::vector<Figure>& figures, const std::string& name,
                       const std::vector<cgfs::Count>& counts, cgfs::Count scale_max) {
  const Canvas canvas = RenderFigureNamed(figures, name);
  cgfs::Count total = 0;
  for (const cgfs::Count count : counts) {
    total += std::max(count, cgfs::Count{0});
  }
  CHECK(MeasuredByFigureNamed(figures, name) ==
        Spaced(total) + " in all, at most " + Spaced(Max(counts)));
  const Image& image = canvas.GetImage();
  const int above_strip = image.Height() - CostStripHeight(image.Height()) - 1;
  cgfs::Count wrong = 0;
  for (int row = 0; row < above_strip; ++row) {
    for (int column = 0; column < image.Width(); ++column) {
      const double count = static_cast<double>(counts[row * image.Width() + column]);
      const Rgb8 expected =
          count < 0 ? kCostNothing : CostRamp(CostPosition(count, static_cast<double>(scale_max)));
      const bool differs = image.At(column, row) != expected;
      if (differs && wrong == 0) {
        UNSCOPED_INFO(name << ": first wrong pixel: column " << column << ", row " << row);
      }
      wrong += differs;
    }
  }
  CHECK(wrong == 0);
}

}  // namespace cgfs::test
