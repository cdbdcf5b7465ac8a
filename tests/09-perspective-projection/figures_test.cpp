// The chapter's figures, pixel by pixel and as a whole image.
#include <catch2/catch.hpp>

#include "golden.h"
#include "pixels.h"
#include "printing.h"
#include "scenes.h"

using cgfs::Rgb8;
using cgfs::test::CheckAgainstGolden;
using cgfs::test::RenderFigureNamed;

TEST_CASE("pinned pixels of the cube", "[figures]") {
  const Canvas canvas = RenderFigureNamed(Figures(), "fig-9-4");
  CHECK(canvas.GetPixel(-240, 0) == Rgb8{0, 0, 255});    // front face, left edge
  CHECK(canvas.GetPixel(-180, 60) == Rgb8{0, 0, 255});   // front face, top edge
  CHECK(canvas.GetPixel(-200, 0) == Rgb8{255, 0, 0});    // back face, left edge
  CHECK(canvas.GetPixel(-100, 0) == Rgb8{255, 0, 0});    // back face, right edge
  CHECK(canvas.GetPixel(-220, -55) == Rgb8{0, 255, 0});  // from vAf to vAb
  CHECK(canvas.GetPixel(-160, 0) == Rgb8{255, 255, 255});
  CHECK(canvas.GetPixel(0, 0) == Rgb8{255, 255, 255});
}

TEST_CASE("the book's cube: only part of its back face and edges reach the canvas", "[figures]") {
  const Canvas canvas = RenderFigureNamed(Figures(), "book-listing-cube");
  long blue = 0;
  for (const auto& [x, y] : cgfs::test::DrawnPixels(canvas)) {
    blue += canvas.GetPixel(x, y) == Rgb8{0, 0, 255};
  }
  CHECK(blue == 0);                                       // the front face is all off-canvas
  CHECK(canvas.GetPixel(-300, 0) == Rgb8{255, 0, 0});     // back face, left edge
  CHECK(canvas.GetPixel(0, -300) == Rgb8{255, 0, 0});     // back face, bottom edge
  CHECK(canvas.GetPixel(-300, -300) == Rgb8{0, 255, 0});  // where an edge enters the canvas
  CHECK(canvas.GetPixel(0, 0) == Rgb8{255, 255, 255});
}

TEST_CASE("pinned pixels of the cube on a 600x400 canvas with a 1.5 x 1 viewport", "[figures]") {
  // Square pixels: 400 to a viewport unit both ways. The front face (z = 5) lands at
  // x = -2/5 and -1/5 of 400 = -160 and -80, y = +-0.5/5 of 400 = +-40; the back face
  // (z = 6) at y = +-33.3. A y scaled by the canvas's width would put the front face's
  // top at 60, an x scaled by its height its left side at -107.
  Canvas canvas(600, 400);
  DrawCube(DemoCube(), canvas, Viewport{1.5, 1, 1});
  CHECK(canvas.GetPixel(-160, 0) == Rgb8{0, 0, 255});   // front face, left edge
  CHECK(canvas.GetPixel(-120, 40) == Rgb8{0, 0, 255});  // front face, top edge
  CHECK(canvas.GetPixel(-80, 0) == Rgb8{0, 0, 255});    // front face, right edge
  CHECK(canvas.GetPixel(-100, 33) == Rgb8{255, 0, 0});  // back face, top edge
  CHECK(canvas.GetPixel(-100, 0) == Rgb8{255, 255, 255});
  CHECK(canvas.GetPixel(-120, 60) == Rgb8{255, 255, 255});
}

TEST_CASE("fig-9-4 matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "fig-9-4");
}

TEST_CASE("book-listing-cube matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "book-listing-cube");
}
