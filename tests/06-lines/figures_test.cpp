// The chapter's figures as whole images.
#include <catch2/catch.hpp>

#include "golden.h"
#include "pixels.h"
#include "scenes.h"

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

TEST_CASE("every draft of DrawLine has a figure, and each draws what it gets wrong", "[figures]") {
  const auto pixels = [](const char* name) {
    return DrawnPixels(RenderFigureNamed(Figures(), name)).size();
  };
  const std::size_t whole = pixels("all-directions");
  // The first two drafts draw only the segments given left to right, and the
  // left-to-right draft draws steep segments with gaps: fewer pixels than the star.
  CHECK(pixels("all-directions-slope-intercept") < whole);
  CHECK(pixels("all-directions-incremental") < whole);
  CHECK(pixels("all-directions-left-to-right") < whole);
  CHECK(pixels("all-directions-x-of-y") < whole);
  CHECK(pixels("all-directions-both-cases") == whole);
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

TEST_CASE("all-directions-slope-intercept matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "all-directions-slope-intercept");
}

TEST_CASE("all-directions-incremental matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "all-directions-incremental");
}

TEST_CASE("all-directions-left-to-right matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "all-directions-left-to-right");
}

TEST_CASE("all-directions-x-of-y matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "all-directions-x-of-y");
}

TEST_CASE("all-directions-both-cases matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "all-directions-both-cases");
}
