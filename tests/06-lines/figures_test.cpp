// Spec §7.3: the chapter's figures as whole images.
#include <catch2/catch.hpp>

#include "golden.h"
#include "pixels.h"
#include "rasterizer.h"

using cgfs::test::CheckAgainstGolden;
using cgfs::test::DrawnPixels;
using cgfs::test::RenderFigureNamed;

TEST_CASE("figure 6-3 shows the gaps, figure 6-5 does not", "[figures]") {
  CHECK(DrawnPixels(RenderFigureNamed(Figures(), "fig-6-1")).size() == 441);
  // 441 + 111, less the one pixel where the two segments cross.
  CHECK(DrawnPixels(RenderFigureNamed(Figures(), "fig-6-3")).size() == 441 + 111 - 1);
  CHECK(DrawnPixels(RenderFigureNamed(Figures(), "fig-6-5")).size() == 441 + 441 - 1);
}

TEST_CASE("the star has its centre and all sixteen tips", "[figures]") {
  const auto pixels = DrawnPixels(RenderFigureNamed(Figures(), "all-directions"));
  CHECK(pixels.count({0, 0}) == 1);
  for (const auto& tip :
       {std::pair{250, 0}, {177, 177}, {-96, 231}, {-250, 0}, {0, -250}, {231, -96}}) {
    CHECK(pixels.count(tip) == 1);
  }
}

TEST_CASE("a draft asked for on the command line adds its own figure", "[figures]") {
  const auto figures = Figures({DrawLineDraft::kXOfY});
  REQUIRE(figures.size() == Figures().size() + 1);
  CHECK(figures.back().name == "all-directions-x-of-y");
}

TEST_CASE("fig-6-1 matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "fig-6-1");
}

TEST_CASE("fig-6-3 matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "fig-6-3");
}

TEST_CASE("fig-6-5 matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "fig-6-5");
}

TEST_CASE("all-directions matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "all-directions");
}
