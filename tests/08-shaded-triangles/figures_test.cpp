// The chapter's figure as a whole image.
#include <catch2/catch.hpp>

#include "golden.h"
#include "printing.h"
#include "scenes.h"

using cgfs::Rgb8;
using cgfs::test::CheckAgainstGolden;
using cgfs::test::RenderFigureNamed;

TEST_CASE("pinned pixels of the shaded triangle", "[figures]") {
  const Canvas canvas = RenderFigureNamed(Figures(), "fig-8-1");
  CHECK(canvas.GetPixel(0, 0) == Rgb8{0, 113, 0});
  CHECK(canvas.GetPixel(0, 100) == Rgb8{0, 174, 0});
  CHECK(canvas.GetPixel(20, 250) == Rgb8{0, 255, 0});
  CHECK(canvas.GetPixel(150, -150) == Rgb8{255, 255, 255});  // outside: white, no outline
}

TEST_CASE("fig-8-1 matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "fig-8-1");
}
