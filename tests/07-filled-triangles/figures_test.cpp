// The chapter's figures, pixel by pixel and as whole images.
#include <catch2/catch.hpp>

#include "golden.h"
#include "pixels.h"
#include "printing.h"
#include "scenes.h"

using cgfs::Rgb8;
using cgfs::test::CheckAgainstGolden;
using cgfs::test::RenderFigureNamed;

TEST_CASE("pinned pixels of the filled triangle with its outline", "[figures]") {
  const Canvas canvas = RenderFigureNamed(Figures(), "fig-7-3");
  CHECK(canvas.GetPixel(0, 0) == Rgb8{0, 255, 0});      // inside
  CHECK(canvas.GetPixel(-200, -250) == Rgb8{0, 0, 0});  // a vertex, on the outline
  CHECK(canvas.GetPixel(20, 250) == Rgb8{0, 0, 0});
  CHECK(canvas.GetPixel(200, 50) == Rgb8{0, 0, 0});
  CHECK(canvas.GetPixel(150, -150) == Rgb8{255, 255, 255});  // outside
  CHECK(canvas.GetPixel(-150, 150) == Rgb8{255, 255, 255});
}

TEST_CASE("fig-7-1 matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "fig-7-1");
}

TEST_CASE("fig-7-3 matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "fig-7-3");
}
