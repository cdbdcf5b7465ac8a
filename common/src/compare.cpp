#include "cgfs/compare.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "cgfs/error.h"

namespace cgfs {

namespace {

constexpr Rgb8 kChangedColor{255, 170, 0};
constexpr Rgb8 kDifferingColor{255, 0, 0};

Rgb8 Faded(Rgb8 pixel) {
  const int luma = (299 * pixel.r + 587 * pixel.g + 114 * pixel.b) / 1000;
  const auto pale = static_cast<std::uint8_t>(255 - (255 - luma) / 4);
  return {pale, pale, pale};
}

std::string Position(int column, int row, int width, int height) {
  std::ostringstream out;
  out << "(" << column << ", " << row << ")";
  if (width % 2 == 0 && height % 2 == 0) {
    out << " = canvas (" << column - width / 2 << ", " << height / 2 - row - 1 << ")";
  }
  return out.str();
}

}  // namespace

long long Tolerance::AllowedDifferingPixels(long long pixels) const {
  return static_cast<long long>(std::floor(differing_fraction * static_cast<double>(pixels)));
}

Comparison CompareImages(const Image& expected, const Image& actual, const Tolerance& tolerance) {
  if (expected.Width() != actual.Width() || expected.Height() != actual.Height()) {
    throw Error("image sizes differ: expected " + std::to_string(expected.Width()) + "x" +
                std::to_string(expected.Height()) + ", got " + std::to_string(actual.Width()) +
                "x" + std::to_string(actual.Height()));
  }
  Comparison result;
  result.pixels = static_cast<long long>(expected.Width()) * expected.Height();
  result.allowed_differing_pixels = tolerance.AllowedDifferingPixels(result.pixels);
  result.difference = Image(expected.Width(), expected.Height());
  result.first_column = expected.Width();
  result.first_row = expected.Height();
  result.last_column = -1;
  result.last_row = -1;

  long long channel_difference_sum = 0;
  for (int row = 0; row < expected.Height(); ++row) {
    for (int column = 0; column < expected.Width(); ++column) {
      const Rgb8 want = expected.At(column, row);
      const Rgb8 got = actual.At(column, row);
      const int largest =
          std::max({std::abs(want.r - got.r), std::abs(want.g - got.g), std::abs(want.b - got.b)});
      channel_difference_sum +=
          std::abs(want.r - got.r) + std::abs(want.g - got.g) + std::abs(want.b - got.b);
      result.max_channel_difference = std::max(result.max_channel_difference, largest);

      Rgb8 shown = Faded(want);
      if (largest > 0) {
        ++result.changed_pixels;
        shown = kChangedColor;
      }
      if (largest > tolerance.channel_levels) {
        ++result.differing_pixels;
        shown = kDifferingColor;
        result.first_column = std::min(result.first_column, column);
        result.first_row = std::min(result.first_row, row);
        result.last_column = std::max(result.last_column, column);
        result.last_row = std::max(result.last_row, row);
      }
      result.difference.Set(column, row, shown);
    }
  }
  result.mean_channel_difference =
      static_cast<double>(channel_difference_sum) / static_cast<double>(result.pixels * 3);
  result.passed = result.differing_pixels <= result.allowed_differing_pixels;
  return result;
}

std::string Describe(const Comparison& c, int width, int height) {
  std::ostringstream out;
  out << (c.passed ? "PASS" : "FAIL") << ": " << c.differing_pixels << " of " << c.pixels
      << " pixels differ by more than the tolerance (allowed: " << c.allowed_differing_pixels
      << ")\n";
  out << "  pixels changed at all: " << c.changed_pixels
      << ", largest channel difference: " << c.max_channel_difference
      << ", mean channel difference: " << c.mean_channel_difference << "\n";
  if (c.differing_pixels > 0) {
    out << "  differing pixels lie between " << Position(c.first_column, c.first_row, width, height)
        << " and " << Position(c.last_column, c.last_row, width, height) << "\n";
  }
  return out.str();
}

}  // namespace cgfs
