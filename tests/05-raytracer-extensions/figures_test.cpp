// The chapter's figures as whole images, and a few pixels that say what they show.
#include <catch2/catch.hpp>

#include "golden.h"
#include "printing.h"
#include "scenes.h"

using cgfs::Rgb8;
using cgfs::test::CheckAgainstGolden;
using cgfs::test::RenderFigureNamed;

TEST_CASE("fig-5-1-camera matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "fig-5-1-camera");
}

TEST_CASE("sphere-field-100 matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "sphere-field-100");
}

TEST_CASE("sphere-field-1000 matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "sphere-field-1000");
}

TEST_CASE("sphere-field-10000 matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "sphere-field-10000");
}

TEST_CASE("sphere-field-100000 matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "sphere-field-100000");
}

TEST_CASE("triangles matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "triangles");
}

TEST_CASE("torus-mesh matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "torus-mesh");
}

TEST_CASE("csg-operations matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "csg-operations");
}

TEST_CASE("csg-lens matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "csg-lens");
}

TEST_CASE("csg-death-star matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "csg-death-star");
}

TEST_CASE("csg-nested matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "csg-nested");
}

TEST_CASE("transparency matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "transparency");
}

TEST_CASE("refraction-glass-sphere matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "refraction-glass-sphere");
}

TEST_CASE("refraction-magnifying-glass matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "refraction-magnifying-glass");
}

TEST_CASE("thin-wires matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "thin-wires");
}

TEST_CASE("subsampling-thin-wires matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "subsampling-thin-wires");
}

TEST_CASE("supersampling-4 matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "supersampling-4");
}

TEST_CASE("supersampling-9 matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "supersampling-9");
}

TEST_CASE("supersampling-16 matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "supersampling-16");
}

TEST_CASE("supersampling-adaptive matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "supersampling-adaptive");
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
