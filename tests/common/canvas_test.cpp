// The canvas coordinates of book chapter 1 (docs/conventions.md, "The canvas").
#include <catch2/catch.hpp>

#include <stdexcept>
#include <vector>

#include "cgfs/canvas.h"

using cgfs::Canvas;
using cgfs::Rgb8;
using cgfs::ScreenPoint;

TEST_CASE("canvas corners and centre map to memory with Sy = Ch/2 - y - 1", "[canvas]") {
  const Canvas canvas(600, 600);
  CHECK(canvas.ToScreen(-300, 299) == ScreenPoint{0, 0});
  CHECK(canvas.ToScreen(0, 0) == ScreenPoint{300, 299});
  CHECK(canvas.ToScreen(299, -300) == ScreenPoint{599, 599});
  CHECK(canvas.ToScreen(-300, -300) == ScreenPoint{0, 599});
  CHECK(canvas.ToScreen(299, 299) == ScreenPoint{599, 0});
}

TEST_CASE("pixels just outside the canvas have no screen position", "[canvas]") {
  const Canvas canvas(600, 600);
  CHECK_FALSE(canvas.ToScreen(300, 0));
  CHECK_FALSE(canvas.ToScreen(0, 300));
  CHECK_FALSE(canvas.ToScreen(-301, 0));
  CHECK_FALSE(canvas.ToScreen(0, -301));
}

TEST_CASE("ToCanvas undoes ToScreen at every pixel of a canvas that is not square", "[canvas]") {
  const Canvas canvas(6, 4);
  CHECK(canvas.ToCanvas(0, 0) == cgfs::CanvasPoint{-3, 1});  // the top-left corner
  CHECK(canvas.ToCanvas(5, 3) == cgfs::CanvasPoint{2, -2});  // the bottom-right corner
  for (int row = 0; row < canvas.Height(); ++row) {
    for (int column = 0; column < canvas.Width(); ++column) {
      const cgfs::CanvasPoint point = canvas.ToCanvas(column, row);
      CHECK(canvas.ToScreen(point.x, point.y) == ScreenPoint{column, row});
    }
  }
}

TEST_CASE("PutPixel writes where ToScreen says and ignores pixels off the canvas", "[canvas]") {
  Canvas canvas(600, 600, cgfs::kWhite);
  canvas.PutPixel(-300, 299, cgfs::kRed);
  canvas.PutPixel(0, 0, cgfs::kGreen);
  canvas.PutPixel(299, -300, cgfs::kBlue);
  const cgfs::Image before = canvas.GetImage();
  canvas.PutPixel(300, 0, cgfs::kBlack);
  canvas.PutPixel(0, 300, cgfs::kBlack);
  canvas.PutPixel(-100000, 100000, cgfs::kBlack);
  CHECK(canvas.GetImage() == before);

  const cgfs::Image& image = canvas.GetImage();
  CHECK(image.At(0, 0) == Rgb8{255, 0, 0});
  CHECK(image.At(300, 299) == Rgb8{0, 255, 0});
  CHECK(image.At(599, 599) == Rgb8{0, 0, 255});
  CHECK(image.At(1, 0) == Rgb8{255, 255, 255});
  CHECK(canvas.GetPixel(0, 0) == Rgb8{0, 255, 0});
}

TEST_CASE("a full-canvas half-open loop touches every pixel exactly once", "[canvas]") {
  Canvas canvas(8, 6, cgfs::kWhite);
  int visits = 0;
  for (int x = -canvas.Width() / 2; x < canvas.Width() / 2; ++x) {
    for (int y = -canvas.Height() / 2; y < canvas.Height() / 2; ++y) {
      REQUIRE(canvas.ToScreen(x, y));
      canvas.PutPixel(x, y, cgfs::kBlack);
      ++visits;
    }
  }
  CHECK(visits == 8 * 6);
  CHECK(canvas.GetImage() == cgfs::Image(8, 6, Rgb8{0, 0, 0}));
}

TEST_CASE("canvas sizes must be positive and even", "[canvas]") {
  CHECK_THROWS_AS(Canvas(601, 600), std::invalid_argument);
  CHECK_THROWS_AS(Canvas(600, 0), std::invalid_argument);
  CHECK_THROWS_AS(Canvas(-2, 2), std::invalid_argument);
  CHECK_NOTHROW(Canvas(2, 2));
}

TEST_CASE("GetPixel refuses a pixel off the canvas", "[canvas]") {
  const Canvas canvas(4, 4);
  CHECK_THROWS_AS(canvas.GetPixel(2, 0), std::out_of_range);
}

TEST_CASE(
    "The canvas counts every PutPixel, at its pixel or off the canvas, while a Tallying lives",
    "[canvas]") {
  Canvas canvas(4, 2);
  canvas.PutPixel(-2, 0, cgfs::kRed);  // before: not counted
  std::vector<cgfs::Count> counts;
  cgfs::Count total = 0;
  {
    const cgfs::Tallying tallying(cgfs::kPixelsPut, 4, 2);
    canvas.PutPixel(-2, 0, cgfs::kRed);  // column 0, row 0
    canvas.PutPixel(-2, 0, cgfs::kBlue);
    canvas.PutPixel(1, -1, cgfs::kRed);  // column 3, row 1
    canvas.PutPixel(2, 0, cgfs::kRed);   // off the canvas: in the total only
    counts = tallying.PerPixel();
    total = tallying.Total();
  }
  canvas.PutPixel(-2, 0, cgfs::kRed);  // after: not counted
  CHECK(counts == std::vector<cgfs::Count>{2, 0, 0, 0, 0, 0, 0, 1});
  CHECK(total == 4);
}
