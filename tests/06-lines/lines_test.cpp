// Interpolate and the final DrawLine, pixel by pixel, on their cases in
// tests/cases/06-lines.json (shared with the runners for other languages), and
// properties of long lines. Every later rasterizer chapter keeps lines.cpp unchanged
// and runs these tests too.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <set>
#include <utility>
#include <vector>

#include "cases.h"
#include "lines.h"
#include "pixels.h"

TEST_CASE("Interpolate: the cases of 06-lines.json", "[interpolate]") {
  using cgfs::test::ToNumber;
  for (const cgfs::test::FunctionCase& c : cgfs::test::CasesOf("06-lines.json", "Interpolate")) {
    INFO(c.Describe());
    const std::vector<double> values =
        Interpolate(static_cast<int>(ToNumber(c.args.at("i0"))), ToNumber(c.args.at("d0")),
                    static_cast<int>(ToNumber(c.args.at("i1"))), ToNumber(c.args.at("d1")));
    CHECK_THAT(cgfs::test::AsNumbers(values), cgfs::test::MatchesCase(c));
  }
}

TEST_CASE("DrawLine: the cases of 06-lines.json", "[draw-line]") {
  using cgfs::test::ToNumber;
  const auto point = [](const nlohmann::json& P) {
    return Point{static_cast<int>(ToNumber(P.at(0))), static_cast<int>(ToNumber(P.at(1)))};
  };
  for (const cgfs::test::FunctionCase& c : cgfs::test::CasesOf("06-lines.json", "DrawLine")) {
    INFO(c.Describe());
    const nlohmann::json& size = c.given.at("canvas");
    Canvas canvas(size.at("width").get<int>(), size.at("height").get<int>(),
                  cgfs::test::kCaseBackground);
    DrawLine(point(c.args.at("P0")), point(c.args.at("P1")),
             cgfs::test::ToColor(c.args.at("color")), canvas);
    CHECK_THAT(cgfs::test::DrawnPixelsAsNumbers(canvas), cgfs::test::MatchesCase(c));
  }
}

TEST_CASE("Interpolate does not drift: the last value is d1", "[interpolate]") {
  // Accumulating d += a would add up rounding errors over hundreds of steps.
  for (const auto& [i1, d1] : {std::pair{500, 220.0}, std::pair{440, 220.0}, std::pair{301, 7.0}}) {
    const std::vector<double> values = Interpolate(0, 0, i1, d1);
    REQUIRE(values.size() == static_cast<std::size_t>(i1 + 1));
    CHECK(values.back() == d1);
  }
}

using cgfs::test::DrawnPixels;
using Pixels = std::set<std::pair<int, int>>;

namespace {

Pixels LinePixels(Point P0, Point P1) {
  Canvas canvas(600, 600);
  DrawLine(P0, P1, cgfs::kBlack, canvas);
  return DrawnPixels(canvas);
}

// Exactly one pixel for every step along the major axis, each next to the one
// before it (8-connected): no gaps, no doubled pixels.
void CheckOnePixelPerStep(const Pixels& pixels, Point P0, Point P1) {
  const bool x_major = std::abs(P1.x - P0.x) > std::abs(P1.y - P0.y);
  const int from = x_major ? std::min(P0.x, P1.x) : std::min(P0.y, P1.y);
  const int to = x_major ? std::max(P0.x, P1.x) : std::max(P0.y, P1.y);
  REQUIRE(pixels.size() == static_cast<std::size_t>(to - from + 1));
  std::vector<int> minor(static_cast<std::size_t>(to - from + 1), 0);
  std::vector<int> count(minor.size(), 0);
  for (const auto& [x, y] : pixels) {
    const int major = x_major ? x : y;
    REQUIRE(major >= from);
    REQUIRE(major <= to);
    ++count[static_cast<std::size_t>(major - from)];
    minor[static_cast<std::size_t>(major - from)] = x_major ? y : x;
  }
  for (std::size_t i = 0; i < count.size(); ++i) {
    CHECK(count[i] == 1);
    if (i > 0) {
      CHECK(std::abs(minor[i] - minor[i - 1]) <= 1);
    }
  }
}

}  // namespace

TEST_CASE("DrawLine: the shallow segment of the chapter", "[draw-line]") {
  const Pixels pixels = LinePixels({-200, -100}, {240, 120});
  CHECK(pixels.size() == 441);
  CHECK(pixels.count({-200, -100}) == 1);
  CHECK(pixels.count({0, 0}) == 1);
  CHECK(pixels.count({240, 120}) == 1);
  // At x = -1 the exact y is -0.5: truncation toward zero gives 0 (floor would give -1).
  CHECK(pixels.count({-1, 0}) == 1);
  CHECK(pixels.count({-1, -1}) == 0);
  CheckOnePixelPerStep(pixels, {-200, -100}, {240, 120});
}

TEST_CASE("DrawLine: the steep segment of the chapter", "[draw-line]") {
  const Pixels pixels = LinePixels({-50, -200}, {60, 240});
  CHECK(pixels.size() == 441);
  CHECK(pixels.count({-50, -200}) == 1);
  CHECK(pixels.count({60, 240}) == 1);
  CHECK(pixels.count({0, 0}) == 1);
  CHECK(pixels.count({0, 1}) == 1);
  CheckOnePixelPerStep(pixels, {-50, -200}, {60, 240});
}

TEST_CASE("DrawLine: horizontal and vertical segments", "[draw-line]") {
  const Pixels horizontal = LinePixels({-10, 5}, {10, 5});
  CHECK(horizontal.size() == 21);
  CheckOnePixelPerStep(horizontal, {-10, 5}, {10, 5});
  const Pixels vertical = LinePixels({3, -7}, {3, 7});
  CHECK(vertical.size() == 15);
  CheckOnePixelPerStep(vertical, {3, -7}, {3, 7});
}

TEST_CASE("DrawLine: reversed end points draw the same pixels", "[draw-line]") {
  const Point cases[][2] = {{{-200, -100}, {240, 120}}, {{-50, -200}, {60, 240}},
                            {{0, 0}, {50, 100}},        {{0, 0}, {100, 50}},
                            {{-30, 40}, {30, -40}},     {{10, -3}, {-290, 1}}};
  for (const auto& segment : cases) {
    CHECK(LinePixels(segment[0], segment[1]) == LinePixels(segment[1], segment[0]));
    CheckOnePixelPerStep(LinePixels(segment[1], segment[0]), segment[0], segment[1]);
  }
}

TEST_CASE("DrawLine: a zero-length segment is one pixel", "[draw-line]") {
  CHECK(LinePixels({7, -3}, {7, -3}) == Pixels{{7, -3}});
}

TEST_CASE("DrawLine: a 45-degree segment, where |dx| == |dy|", "[draw-line]") {
  const Pixels pixels = LinePixels({-5, -5}, {5, 5});
  CHECK(pixels.size() == 11);
  for (int i = -5; i <= 5; ++i) {
    CHECK(pixels.count({i, i}) == 1);
  }
}
