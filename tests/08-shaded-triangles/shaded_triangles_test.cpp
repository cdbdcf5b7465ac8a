// DrawShadedTriangle (Listing 8-1): on its cases, and with values worked out by hand. Every later
// rasterizer chapter keeps it unchanged and runs these tests too.
#include <catch2/catch.hpp>

#include <set>
#include <utility>
#include <vector>

#include "cases.h"
#include "pixels.h"
#include "printing.h"
#include "shaded_triangles.h"

using cgfs::test::DrawnPixels;
using Pixels = std::set<std::pair<int, int>>;
using cgfs::test::IsSameImageAs;

namespace {

Pixels ShadedPixels(Point P0, Point P1, Point P2) {
  Canvas canvas(600, 600);
  DrawShadedTriangle(P0, P1, P2, cgfs::kBlack, canvas);
  return DrawnPixels(canvas);
}

Canvas Shaded(Point P0, Point P1, Point P2) {
  Canvas canvas(600, 600);
  DrawShadedTriangle(P0, P1, P2, cgfs::kGreen, canvas);
  return canvas;
}

constexpr Point kShaded0{-200, -250, 0.3}, kShaded1{200, 50, 0.1}, kShaded2{20, 250, 1.0};

}  // namespace

// DrawShadedTriangle on the cases of tests/cases/08-shaded-triangles.json (a 20 x 20
// canvas, every pixel and its colour listed), shared with the runners for other languages.
TEST_CASE("DrawShadedTriangle: the cases of 08-shaded-triangles.json", "[shaded]") {
  using cgfs::test::ToNumber;
  const auto point = [](const nlohmann::json& P) {
    return Point{static_cast<int>(ToNumber(P.at(0))), static_cast<int>(ToNumber(P.at(1))),
                 ToNumber(P.at(2))};
  };
  for (const cgfs::test::FunctionCase& c :
       cgfs::test::CasesOf("08-shaded-triangles.json", "DrawShadedTriangle")) {
    INFO(c.Describe());
    const nlohmann::json& size = c.given.at("canvas");
    Canvas canvas(size.at("width").get<int>(), size.at("height").get<int>(),
                  cgfs::test::kCaseBackground);
    DrawShadedTriangle(point(c.args.at("P0")), point(c.args.at("P1")), point(c.args.at("P2")),
                       cgfs::test::ToColor(c.args.at("color")), canvas);
    CHECK_THAT(cgfs::test::DrawnPixelsAsNumbers(canvas), cgfs::test::MatchesCase(c));
  }
}

TEST_CASE("DrawShadedTriangle: pinned intensities", "[shaded]") {
  const Canvas canvas = Shaded(kShaded0, kShaded1, kShaded2);
  // Inside the row y = 0, h runs from 0.65 at x = -90 to 0.133 at x = 133.
  CHECK(canvas.GetPixel(0, 0) == cgfs::Rgb8{0, 113, 0});    // h = 0.441480, raw 112.577
  CHECK(canvas.GetPixel(-90, 0) == cgfs::Rgb8{0, 166, 0});  // raw 165.75
  CHECK(canvas.GetPixel(133, 0) == cgfs::Rgb8{0, 34, 0});
  CHECK(canvas.GetPixel(0, 100) == cgfs::Rgb8{0, 174, 0});  // raw 174.313
  // The vertices keep their own h.
  CHECK(canvas.GetPixel(20, 250) == cgfs::Rgb8{0, 255, 0});
  // 255 * 0.3 = 76.5 and 255 * 0.1 = 25.5 are rounding ties: the interpolated h
  // may end a hair either side of the vertex's own, so either neighbour is right.
  CHECK(canvas.GetPixel(-200, -250).g >= 76);
  CHECK(canvas.GetPixel(-200, -250).g <= 77);
  CHECK(canvas.GetPixel(200, 50).g >= 25);
  CHECK(canvas.GetPixel(200, 50).g <= 26);
}

TEST_CASE("DrawShadedTriangle: the middle of a side has the mean of its ends' h", "[shaded]") {
  const Canvas canvas = Shaded(kShaded0, kShaded1, kShaded2);
  // Side P0-P2 at y = 0 is its midpoint: x = -90, h = (0.3 + 1.0) / 2 = 0.65.
  CHECK(canvas.GetPixel(-90, 0).g == cgfs::ToChannel(255 * 0.65));
  // Side P0-P1 at y = -100: x = 0, h = (0.3 + 0.1) / 2 = 0.2; it is the row's right end.
  CHECK(canvas.GetPixel(0, -100).g == cgfs::ToChannel(255 * 0.2));
  // Side P1-P2 at y = 150: x = 110, h = (0.1 + 1.0) / 2 = 0.55.
  CHECK(canvas.GetPixel(110, 150).g == cgfs::ToChannel(255 * 0.55));
}

TEST_CASE("DrawShadedTriangle: h = 1 everywhere is DrawFilledTriangle", "[shaded]") {
  Canvas filled(600, 600);
  DrawFilledTriangle({-200, -250}, {200, 50}, {20, 250}, cgfs::kGreen, filled);
  CHECK_THAT(Shaded({-200, -250, 1}, {200, 50, 1}, {20, 250, 1}).GetImage(),
             IsSameImageAs(filled.GetImage()));
}

TEST_CASE("DrawShadedTriangle: the intensity travels with its vertex", "[shaded]") {
  const cgfs::Image expected = Shaded(kShaded0, kShaded1, kShaded2).GetImage();
  CHECK_THAT(Shaded(kShaded2, kShaded1, kShaded0).GetImage(), IsSameImageAs(expected));
  CHECK_THAT(Shaded(kShaded1, kShaded0, kShaded2).GetImage(), IsSameImageAs(expected));
  CHECK_THAT(Shaded(kShaded2, kShaded0, kShaded1).GetImage(), IsSameImageAs(expected));
}

TEST_CASE("DrawShadedTriangle: degenerate triangles draw without crashing", "[shaded]") {
  CHECK(ShadedPixels({-5, 3, 0.5}, {5, 3, 0.5}, {0, 3, 0.5}).size() == 11);
  CHECK(ShadedPixels({0, 0, 1}, {0, 0, 1}, {10, 20, 1}).size() == 21);
  CHECK(ShadedPixels({4, 4, 1}, {4, 4, 1}, {4, 4, 1}) == Pixels{{4, 4}});
  CHECK(ShadedPixels({0, 0, 1}, {5, 10, 1}, {10, 20, 1}).size() == 21);
}
