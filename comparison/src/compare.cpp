#include "comparison/compare.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <iomanip>
#include <iterator>
#include <map>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <utility>

namespace cgfs {

namespace {

constexpr Rgb8 kMissingColor = kDifferenceColours[0].colour;
constexpr Rgb8 kExtraColor = kDifferenceColours[1].colour;
constexpr Rgb8 kRecolouredColor = kDifferenceColours[2].colour;
constexpr Rgb8 kChangedColor = kDifferenceColours[3].colour;

int LargestChannelDifference(Rgb8 a, Rgb8 b) {
  return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
}

// The most common colour of an image over the pixels where counted(column, row):
// over all of a figure, its background.
template <typename Counted>
Rgb8 MostCommonColour(const Image& image, Counted counted) {
  std::map<std::tuple<int, int, int>, long long> counts;
  for (int row = 0; row < image.Height(); ++row) {
    for (int column = 0; column < image.Width(); ++column) {
      if (counted(column, row)) {
        const Rgb8 pixel = image.At(column, row);
        ++counts[{pixel.r, pixel.g, pixel.b}];
      }
    }
  }
  const auto most =
      std::max_element(counts.begin(), counts.end(),
                       [](const auto& a, const auto& b) { return a.second < b.second; });
  const auto [r, g, b] = most->first;
  return {static_cast<std::uint8_t>(r), static_cast<std::uint8_t>(g), static_cast<std::uint8_t>(b)};
}

// How many pixels differ beyond the tolerance when actual(column, row) is compared
// with recolour(expected(source(column, row))), over the pixels whose source is
// inside.
template <typename Source, typename Recolour = std::identity>
long long DifferingUnder(const Image& expected, const Image& actual, int channel_levels,
                         Source source, Recolour recolour = {}) {
  long long differing = 0;
  for (int row = 0; row < actual.Height(); ++row) {
    for (int column = 0; column < actual.Width(); ++column) {
      const auto [from_column, from_row] = source(column, row);
      if (from_column < 0 || from_row < 0 || from_column >= expected.Width() ||
          from_row >= expected.Height()) {
        continue;
      }
      if (LargestChannelDifference(recolour(expected.At(from_column, from_row)),
                                   actual.At(column, row)) > channel_levels) {
        ++differing;
      }
    }
  }
  return differing;
}

std::pair<int, int> SamePlace(int column, int row) {
  return {column, row};
}

std::string Levels(Rgb8 colour) {
  return std::to_string(colour.r) + ", " + std::to_string(colour.g) + ", " +
         std::to_string(colour.b);
}

// Whether the images match once our background is painted in yours: the scene
// is right and only the colour of the background differs.
std::string DiagnoseBackground(const Image& expected, const Image& actual,
                               const Tolerance& tolerance, long long allowed, Rgb8 ours,
                               Rgb8 yours) {
  const auto repainted = [&](Rgb8 pixel) { return pixel == ours ? yours : pixel; };
  if (DifferingUnder(expected, actual, tolerance.channel_levels, SamePlace, repainted) > allowed) {
    return "";
  }
  return "only the background differs: yours is (" + Levels(yours) + "), ours (" + Levels(ours) +
         "); check the background colour";
}

// Whether yours is ours with every channel scaled by one factor, or moved by one
// number of levels (clamped to 0..255): the shapes are right, the brightness is not.
std::string DiagnoseBrightness(const Image& expected, const Image& actual,
                               const Tolerance& tolerance, long long allowed) {
  // Least squares over every channel: factor = sum(a e) / sum(e e); offset = mean of a - e
  // where neither is clamped.
  double products = 0, squares = 0, offsets = 0, unclamped = 0;
  for (int row = 0; row < expected.Height(); ++row) {
    for (int column = 0; column < expected.Width(); ++column) {
      const Rgb8 e = expected.At(column, row);
      const Rgb8 a = actual.At(column, row);
      for (const auto& [ours, yours] : {std::pair{e.r, a.r}, {e.g, a.g}, {e.b, a.b}}) {
        products += static_cast<double>(ours) * yours;
        squares += static_cast<double>(ours) * ours;
        if (ours > 0 && ours < 255 && yours > 0 && yours < 255) {
          offsets += static_cast<double>(yours) - ours;
          unclamped += 1;
        }
      }
    }
  }
  const auto level = [](double value) {
    return static_cast<std::uint8_t>(std::clamp(std::round(value), 0.0, 255.0));
  };
  // To two decimals, as people write factors: off by at most 1.3 levels at 255.
  const double factor = squares > 0 ? std::round(100 * products / squares) / 100 : 1;
  const auto scaled = [&](Rgb8 p) {
    return Rgb8{level(p.r * factor), level(p.g * factor), level(p.b * factor)};
  };
  if (std::abs(factor - 1) >= 0.01 &&
      DifferingUnder(expected, actual, tolerance.channel_levels, SamePlace, scaled) <= allowed) {
    std::ostringstream words;
    words << "your image is ours with every channel times " << std::setprecision(3) << factor
          << (factor < 1 ? " (darker)" : " (brighter)")
          << ": check how colours become 0-255 levels, and the lights' intensities";
    return words.str();
  }
  const int offset = unclamped > 0 ? static_cast<int>(std::lround(offsets / unclamped)) : 0;
  const auto moved = [&](Rgb8 p) {
    return Rgb8{level(p.r + offset), level(p.g + offset), level(p.b + offset)};
  };
  if (std::abs(offset) > tolerance.channel_levels &&
      DifferingUnder(expected, actual, tolerance.channel_levels, SamePlace, moved) <= allowed) {
    return "your image is ours " + std::to_string(std::abs(offset)) + " levels " +
           (offset < 0 ? "darker" : "brighter") +
           " everywhere: check how colours become 0-255 levels";
  }
  return "";
}

// The first of the usual slips under which the images match: a pixel off in x or
// y (the canvas-to-screen mapping), a flip (y growing down instead of up), the
// channels written B, G, R, another background colour (ours and yours given), or
// another brightness.
std::string Diagnose(const Image& expected, const Image& actual, const Tolerance& tolerance,
                     long long allowed, Rgb8 background, Rgb8 their_background) {
  struct Slip {
    int dx, dy;
    const char* words;
  };
  static constexpr Slip kShifts[] = {
      {0, 1, "your image is ours moved one row down: check the Sy mapping, Sy = Ch/2 - y - 1"},
      {0, -1, "your image is ours moved one row up: check the Sy mapping, Sy = Ch/2 - y - 1"},
      {1, 0, "your image is ours moved one column right: check the Sx mapping, Sx = Cw/2 + x"},
      {-1, 0, "your image is ours moved one column left: check the Sx mapping, Sx = Cw/2 + x"},
  };
  for (const Slip& slip : kShifts) {
    const long long differing =
        DifferingUnder(expected, actual, tolerance.channel_levels, [&](int column, int row) {
          return std::pair{column - slip.dx, row - slip.dy};
        });
    if (differing <= allowed) {
      return slip.words;
    }
  }
  const int w = expected.Width();
  const int h = expected.Height();
  if (DifferingUnder(expected, actual, tolerance.channel_levels, [&](int column, int row) {
        return std::pair{column, h - 1 - row};
      }) <= allowed) {
    return "your image is ours upside down: canvas y grows upwards, rows downwards "
           "(Sy = Ch/2 - y - 1)";
  }
  // Canvas y negated (a -y in CanvasToViewport): your row r shows our canvas row -y,
  // which is our row h - 2 - r.
  if (DifferingUnder(expected, actual, tolerance.channel_levels, [&](int column, int row) {
        return std::pair{column, h - 2 - row};
      }) <= allowed) {
    return "your image is ours upside down about canvas y = 0: check the sign of y in "
           "CanvasToViewport and the Sy mapping (Sy = Ch/2 - y - 1)";
  }
  if (DifferingUnder(expected, actual, tolerance.channel_levels, [&](int column, int row) {
        return std::pair{w - 1 - column, row};
      }) <= allowed) {
    return "your image is ours mirrored left to right: check the Sx mapping, Sx = Cw/2 + x";
  }
  const auto swap_red_and_blue = [](Rgb8 pixel) { return Rgb8{pixel.b, pixel.g, pixel.r}; };
  if (DifferingUnder(expected, actual, tolerance.channel_levels, SamePlace, swap_red_and_blue) <=
      allowed) {
    return "your image is ours with red and blue swapped: write the channels in the order "
           "R, G, B";
  }
  if (their_background != background) {
    if (std::string words =
            DiagnoseBackground(expected, actual, tolerance, allowed, background, their_background);
        !words.empty()) {
      return words;
    }
  }
  return DiagnoseBrightness(expected, actual, tolerance, allowed);
}

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

std::string DifferenceLegend() {
  std::string legend;
  for (const DifferenceColour& each : kDifferenceColours) {
    if (!legend.empty()) {  // the last, the pixels within the tolerance, after a ';'
      legend += &each == std::end(kDifferenceColours) - 1 ? "; " : ", ";
    }
    legend += std::string(each.name) + ": " + each.meaning;
  }
  return legend;
}

Comparison CompareImages(const Image& expected, const Image& actual, const Tolerance& tolerance) {
  if (expected.Width() != actual.Width() || expected.Height() != actual.Height()) {
    throw std::invalid_argument("image sizes differ: expected " + std::to_string(expected.Width()) +
                                "x" + std::to_string(expected.Height()) + ", got " +
                                std::to_string(actual.Width()) + "x" +
                                std::to_string(actual.Height()));
  }
  Comparison result;
  result.pixels = static_cast<long long>(expected.Width()) * expected.Height();
  result.allowed_differing_pixels = tolerance.AllowedDifferingPixels(result.pixels);
  result.difference = Image(expected.Width(), expected.Height());
  result.first_column = expected.Width();
  result.first_row = expected.Height();
  result.last_column = -1;
  result.last_row = -1;

  // Ours is our most common colour; yours is what you drew most where ours shows.
  const Rgb8 background = MostCommonColour(expected, [](int, int) { return true; });
  const Rgb8 their_background = MostCommonColour(
      actual, [&](int column, int row) { return expected.At(column, row) == background; });
  long long channel_difference_sum = 0;
  for (int row = 0; row < expected.Height(); ++row) {
    for (int column = 0; column < expected.Width(); ++column) {
      const Rgb8 want = expected.At(column, row);
      const Rgb8 got = actual.At(column, row);
      const int largest = LargestChannelDifference(want, got);
      channel_difference_sum +=
          std::abs(want.r - got.r) + std::abs(want.g - got.g) + std::abs(want.b - got.b);
      result.max_channel_difference = std::max(result.max_channel_difference, largest);

      Rgb8 shown = Faded(want);
      if (largest > 0) {
        ++result.changed_pixels;
        shown = kChangedColor;
      }
      if (largest > tolerance.channel_levels) {
        if (result.differing_pixels++ == 0) {
          result.first_differing = {column, row, want, got};
        }
        const bool background_in_ours = want == background;
        const bool background_in_yours = got == their_background;
        if (background_in_ours && !background_in_yours) {
          ++result.extra_pixels;
          shown = kExtraColor;
        } else if (!background_in_ours && background_in_yours) {
          ++result.missing_pixels;
          shown = kMissingColor;
        } else {
          ++result.recoloured_pixels;
          shown = kRecolouredColor;
        }
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
  if (!result.passed) {
    result.diagnosis = Diagnose(expected, actual, tolerance, result.allowed_differing_pixels,
                                background, their_background);
  }
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
    const Comparison::Pixel& first = c.first_differing;
    out << "  first differing pixel: " << Position(first.column, first.row, width, height)
        << ": yours (" << Levels(first.yours) << "), ours (" << Levels(first.ours) << ")\n";
    out << "  of them in ours only (missing): " << c.missing_pixels
        << ", in yours only (extra): " << c.extra_pixels
        << ", in both in another colour: " << c.recoloured_pixels << "\n";
  }
  if (!c.diagnosis.empty()) {
    out << "  diagnosis: " << c.diagnosis << "\n";
  }
  return out.str();
}

}  // namespace cgfs
