#include "program/cost_view.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace cgfs {

// Green's equation 2: the grey level, plus a deviation around it that turns through
// `rotations` turns of the colour wheel and vanishes at black and at white.
Rgb8 CostRamp(double position) {
  constexpr double kStart = 0.5, kRotations = -1.5, kHue = 1.0;
  const double lambda = std::clamp(position, 0.0, 1.0);
  const double amplitude = kHue * lambda * (1 - lambda) / 2;
  const double phi = 2 * std::numbers::pi * (kStart / 3 + kRotations * lambda);
  const double c = std::cos(phi), s = std::sin(phi);
  const double r = lambda + amplitude * (-0.14861 * c + 1.78277 * s);
  const double g = lambda + amplitude * (-0.29227 * c - 0.90649 * s);
  const double b = lambda + amplitude * (1.97294 * c);
  return {ToChannel(255 * r), ToChannel(255 * g), ToChannel(255 * b)};
}

double CostPosition(double count, double scale_max) {
  if (scale_max <= 0) {
    return count > 0 ? 1 : 0;
  }
  return std::clamp(std::log1p(std::max(count, 0.0)) / std::log1p(scale_max), 0.0, 1.0);
}

int CostStripHeight(int canvas_height) {
  return std::max(4, canvas_height / 25);
}

namespace {

// The largest scale whose colours DrawCost works out in advance.
constexpr cgfs::Count kLargestScale = 1 << 20;

void Put(Canvas& canvas, int column, int row, Rgb8 value) {
  const cgfs::CanvasPoint point = canvas.ToCanvas(column, row);
  canvas.PutPixel(point.x, point.y, {value.r, value.g, value.b});
}

// The count the strip shows at `column`: a whole one per block for a few steps, else
// the ramp's own value there.
Rgb8 StripColor(int column, int width, cgfs::Count scale_max) {
  if (scale_max <= kCostStepsMax) {
    const cgfs::Count count = static_cast<cgfs::Count>(column) * (scale_max + 1) / width;
    return CostRamp(CostPosition(static_cast<double>(count), static_cast<double>(scale_max)));
  }
  return CostRamp(width > 1 ? static_cast<double>(column) / (width - 1) : 1.0);
}

}  // namespace

void DrawCost(Canvas& canvas, const std::vector<cgfs::Count>& counts, cgfs::Count scale_max) {
  const int width = canvas.Width(), height = canvas.Height();
  if (counts.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) {
    throw std::invalid_argument("DrawCost: one count per pixel is needed");
  }
  // Each count's colour worked out once (counts above the scale all get its top's).
  const cgfs::Count top = std::max(scale_max, cgfs::Count{0});
  std::vector<Rgb8> colors(static_cast<std::size_t>(std::min(top, kLargestScale)) + 1);
  for (std::size_t count = 0; count < colors.size(); ++count) {
    colors[count] =
        CostRamp(CostPosition(static_cast<double>(count), static_cast<double>(scale_max)));
  }
  for (int row = 0; row < height; ++row) {
    for (int column = 0; column < width; ++column) {
      const cgfs::Count count = counts[static_cast<std::size_t>(row) * width + column];
      Put(canvas, column, row,
          count < 0 ? kCostNothing
          : count < static_cast<cgfs::Count>(colors.size())
              ? colors[static_cast<std::size_t>(count)]
              : CostRamp(CostPosition(static_cast<double>(count), static_cast<double>(scale_max))));
    }
  }
  const int strip = CostStripHeight(height);
  for (int column = 0; column < width; ++column) {
    Put(canvas, column, height - strip - 1, {255, 255, 255});
    const Rgb8 color = StripColor(column, width, scale_max);
    for (int row = height - strip; row < height; ++row) {
      Put(canvas, column, row, color);
    }
  }
}

namespace {

// 1234567 as the captions write it: "1 234 567".
std::string Spaced(cgfs::Count n) {
  const std::string digits = std::to_string(n < 0 ? -n : n);
  std::string spaced = n < 0 ? "-" : "";
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) {
      spaced += ' ';
    }
    spaced += digits[i];
  }
  return spaced;
}

}  // namespace

std::string CostTotals(const std::vector<cgfs::Count>& counts) {
  cgfs::Count total = 0, largest = 0;
  for (const cgfs::Count count : counts) {
    total += std::max(count, cgfs::Count{0});
    largest = std::max(largest, count);
  }
  return Spaced(total) + " in all, at most " + Spaced(largest);
}

}  // namespace cgfs
