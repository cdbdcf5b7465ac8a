// DrawWireframeTriangle and DrawFilledTriangle, pixel by pixel: on their cases, and on
// the chapter's own triangle. Every later rasterizer chapter keeps them unchanged and
// runs these tests too.
#include <catch2/catch.hpp>

#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include "cases.h"
#include "pixels.h"
#include "triangles.h"

using cgfs::test::DrawnPixels;
using cgfs::test::Row;
using Pixels = std::set<std::pair<int, int>>;

namespace {

constexpr Point kP0{-200, -250}, kP1{200, 50}, kP2{20, 250};

Pixels FilledPixels(Point P0, Point P1, Point P2) {
  Canvas canvas(600, 600);
  DrawFilledTriangle(P0, P1, P2, cgfs::kBlack, canvas);
  return DrawnPixels(canvas);
}

}  // namespace

namespace {

// A drawing function of chapter 7 on its cases in tests/cases/07-filled-triangles.json
// (a 20 x 20 canvas, every pixel listed), shared with the runners for other languages.
template <typename Draw>
void CheckTriangleCases(const char* function, Draw draw) {
  using cgfs::test::ToNumber;
  const auto point = [](const nlohmann::json& P) {
    return Point{static_cast<int>(ToNumber(P.at(0))), static_cast<int>(ToNumber(P.at(1)))};
  };
  for (const cgfs::test::FunctionCase& c :
       cgfs::test::CasesOf("07-filled-triangles.json", function)) {
    INFO(c.Describe());
    const nlohmann::json& size = c.given.at("canvas");
    Canvas canvas(size.at("width").get<int>(), size.at("height").get<int>(),
                  cgfs::test::kCaseBackground);
    draw(point(c.args.at("P0")), point(c.args.at("P1")), point(c.args.at("P2")),
         cgfs::test::ToColor(c.args.at("color")), canvas);
    CHECK_THAT(cgfs::test::DrawnPixelsAsNumbers(canvas), cgfs::test::MatchesCase(c));
  }
}

}  // namespace

TEST_CASE("DrawWireframeTriangle: the cases of 07-filled-triangles.json", "[triangle]") {
  CheckTriangleCases("DrawWireframeTriangle",
                     [](Point P0, Point P1, Point P2, const Color& color, Canvas& canvas) {
                       DrawWireframeTriangle(P0, P1, P2, color, canvas);
                     });
}

TEST_CASE("DrawFilledTriangle: the cases of 07-filled-triangles.json", "[triangle]") {
  CheckTriangleCases("DrawFilledTriangle",
                     [](Point P0, Point P1, Point P2, const Color& color, Canvas& canvas) {
                       DrawFilledTriangle(P0, P1, P2, color, canvas);
                     });
}

TEST_CASE("DrawFilledTriangle: rows and the pixel count of the chapter's triangle", "[triangle]") {
  const Pixels pixels = FilledPixels(kP0, kP1, kP2);
  CHECK(pixels.size() == 67215);
  CHECK(Row(pixels, 0) == std::tuple{-90, 133, 224});
  CHECK(Row(pixels, 250) == std::tuple{20, 20, 1});
  CHECK(Row(pixels, -250) == std::tuple{-200, -200, 1});
  CHECK(Row(pixels, 50) == std::tuple{-68, 200, 269});
  CHECK(std::get<2>(Row(pixels, 251)) == 0);
  CHECK(std::get<2>(Row(pixels, -251)) == 0);
}

TEST_CASE("DrawFilledTriangle: every order of the vertices gives the same pixels", "[triangle]") {
  const Pixels expected = FilledPixels(kP0, kP1, kP2);
  CHECK(FilledPixels(kP0, kP2, kP1) == expected);
  CHECK(FilledPixels(kP1, kP0, kP2) == expected);
  CHECK(FilledPixels(kP1, kP2, kP0) == expected);
  CHECK(FilledPixels(kP2, kP0, kP1) == expected);
  CHECK(FilledPixels(kP2, kP1, kP0) == expected);
}

TEST_CASE("DrawFilledTriangle: a flat top or a flat bottom", "[triangle]") {
  // y1 == y2 and y0 == y1: either of the other sides may be the "long" one.
  const Pixels flat_top = FilledPixels({0, 0}, {-10, 10}, {10, 10});
  CHECK(Row(flat_top, 10) == std::tuple{-10, 10, 21});
  CHECK(Row(flat_top, 0) == std::tuple{0, 0, 1});
  CHECK(flat_top.size() == 121);  // 1 + 3 + ... + 21
  const Pixels flat_bottom = FilledPixels({-10, 0}, {10, 0}, {0, 10});
  CHECK(Row(flat_bottom, 0) == std::tuple{-10, 10, 21});
  CHECK(flat_bottom.size() == 121);
}

TEST_CASE("DrawFilledTriangle: degenerate triangles draw without crashing", "[triangle]") {
  // All three on one row: one row, from the first two vertices after sorting.
  const Pixels flat = FilledPixels({-5, 3}, {5, 3}, {0, 3});
  CHECK(flat.size() == 11);
  CHECK(Row(flat, 3) == std::tuple{-5, 5, 11});
  // Two equal vertices: a line-like set along the remaining side.
  const Pixels sliver = FilledPixels({0, 0}, {0, 0}, {10, 20});
  CHECK(sliver.size() == 21);
  CHECK(sliver.count({0, 0}) == 1);
  CHECK(sliver.count({10, 20}) == 1);
  // All three equal: a single pixel.
  CHECK(FilledPixels({4, 4}, {4, 4}, {4, 4}) == Pixels{{4, 4}});
  // Collinear but not horizontal.
  const Pixels collinear = FilledPixels({0, 0}, {5, 10}, {10, 20});
  CHECK(collinear.size() == 21);
}

TEST_CASE("DrawWireframeTriangle draws the three sides", "[triangle]") {
  Canvas canvas(600, 600);
  DrawWireframeTriangle(kP0, kP1, kP2, cgfs::kBlack, canvas);
  Canvas sides(600, 600);
  DrawLine(kP0, kP1, cgfs::kBlack, sides);
  DrawLine(kP1, kP2, cgfs::kBlack, sides);
  DrawLine(kP2, kP0, cgfs::kBlack, sides);
  CHECK(DrawnPixels(canvas) == DrawnPixels(sides));
  CHECK(DrawnPixels(canvas).count({-200, -250}) == 1);
  CHECK(DrawnPixels(canvas).count({200, 50}) == 1);
  CHECK(DrawnPixels(canvas).count({20, 250}) == 1);
}
