// Colours clamped to 0..255 and rounded only when written (their arithmetic is GLM's).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <vector>

#include "cgfs/canvas.h"
#include "cgfs/color.h"

using cgfs::Color;
using cgfs::Rgb8;

TEST_CASE("intermediate colours may leave 0..255 and are clamped only when written", "[color]") {
  const Color raw = 2.0 * Color(192, 64, 32);
  CHECK(raw == Color(384, 128, 64));
  cgfs::Canvas canvas(2, 2);
  canvas.PutPixel(0, 0, raw);
  CHECK(canvas.GetPixel(0, 0) == Rgb8{255, 128, 64});
}

TEST_CASE("a channel is clamped to 0..255, then rounded to nearest", "[color]") {
  CHECK(cgfs::ToChannel(-20) == 0);
  CHECK(cgfs::ToChannel(0.49) == 0);
  CHECK(cgfs::ToChannel(12.4) == 12);
  CHECK(cgfs::ToChannel(12.6) == 13);
  CHECK(cgfs::ToChannel(112.577) == 113);
  CHECK(cgfs::ToChannel(254.6) == 255);
  CHECK(cgfs::ToChannel(296.02) == 255);
}

TEST_CASE("a channel rounds exactly as std::lround: halves up, and at the last bit", "[color]") {
  // Every value a pixel's arithmetic can produce rounds as lround(clamp(v, 0, 255)):
  // the halves, the doubles just below and above them, and a sweep across the range.
  const auto lround_clamped = [](double v) {
    return static_cast<int>(std::lround(std::clamp(v, 0.0, 255.0)));
  };
  std::vector<double> values = {0.0, -0.0, 0.5, 1.5, 127.5, 254.5, 255.0, 1e300, -1e300};
  for (int k = 0; k <= 255; ++k) {
    const double half = k + 0.5;
    values.insert(values.end(), {half, std::nextafter(half, 0.0), std::nextafter(half, 300.0),
                                 static_cast<double>(k), std::nextafter(k + 0.0, -1.0)});
  }
  for (double v = -3; v < 260; v += 0.0137) {
    values.push_back(v);
  }
  for (const double v : values) {
    INFO(std::setprecision(17) << v);
    CHECK(int{cgfs::ToChannel(v)} == lround_clamped(v));
  }
  CHECK(cgfs::ToChannel(std::numeric_limits<double>::quiet_NaN()) == 0);
  CHECK(cgfs::ToChannel(std::numeric_limits<double>::infinity()) == 255);
}
