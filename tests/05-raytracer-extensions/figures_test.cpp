// The chapter's figures as whole images, and a few pixels that say what they show.
#include <catch2/catch.hpp>

#include "golden.h"
#include "printing.h"
#include "scenes.h"

using cgfs::Rgb8;
using cgfs::test::CheckAgainstGolden;
using cgfs::test::RenderFigureNamed;

TEST_CASE("golden images of every figure", "[figures]") {
  for (const cgfs::Figure& figure : Figures({})) {
    SECTION(figure.name) {
      CheckAgainstGolden(CGFS_CHAPTER, Figures({}), figure.name);
    }
  }
}

TEST_CASE("pinned pixels: the Death Star's crater has the small sphere's colour", "[figures]") {
  const Canvas canvas = RenderFigureNamed(Figures({}), "csg-death-star");
  const Rgb8 crater = canvas.GetPixel(-100, 90);
  const Rgb8 hull = canvas.GetPixel(100, -60);
  CHECK(crater.b > crater.r);  // (90, 90, 100): a bluish grey
  CHECK(hull.r == hull.b);     // (160, 160, 160): neutral grey
  CHECK(canvas.GetPixel(0, 250) == Rgb8{0, 0, 0});
}

TEST_CASE("pinned pixels: the magnifying glass shows fewer, larger spheres", "[figures]") {
  // Through the lens the wall's spheres are about four times as large: along a row
  // through the middle, red spheres begin and end far less often inside the lens
  // than outside it.
  const Canvas canvas = RenderFigureNamed(Figures({}), "refraction-magnifying-glass");
  auto red = [&](int x) {
    const Rgb8 pixel = canvas.GetPixel(x, 0);
    return pixel.r > pixel.g + 80;
  };
  auto changes = [&](int x_begin, int x_end) {
    int count = 0;
    for (int x = x_begin; x < x_end; ++x) {
      count += red(x) != red(x + 1);
    }
    return count;
  };
  INFO("inside the lens " << changes(-60, 60) << ", outside " << changes(-190, -70));
  CHECK(changes(-60, 60) * 2 < changes(-190, -70));
}
