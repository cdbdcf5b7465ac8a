// The chapter's figures as whole images, and a few pixels that say what they show.
#include <catch2/catch.hpp>

#include <utility>
#include <vector>

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

TEST_CASE("sphere-field-10000-tests matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "sphere-field-10000-tests");
}

TEST_CASE("sphere-field-10000-tests-without-hierarchy matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "sphere-field-10000-tests-without-hierarchy");
}

TEST_CASE("subsampling-thin-wires-searches matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "subsampling-thin-wires-searches");
}

TEST_CASE("supersampling-adaptive-rays matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "supersampling-adaptive-rays");
}

TEST_CASE("transparency-rays matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "transparency-rays");
}

TEST_CASE("refraction-glass-sphere-rays matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "refraction-glass-sphere-rays");
}

TEST_CASE("refraction-magnifying-glass-rays matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "refraction-magnifying-glass-rays");
}

TEST_CASE("pinned pixels: the Death Star's crater has the small sphere's colour", "[figures]") {
  const Canvas canvas = RenderFigureNamed(Figures({}), "csg-death-star");
  const Rgb8 crater = canvas.GetPixel(-100, 90);
  const Rgb8 hull = canvas.GetPixel(100, -60);
  CHECK(crater.b > crater.r);  // (90, 90, 100): a bluish grey
  CHECK(hull.r == hull.b);     // (160, 160, 160): neutral grey
  CHECK(canvas.GetPixel(0, 250) == Rgb8{0, 0, 0});
}

TEST_CASE("pinned pixels: the magnifying glass shows the F behind it upright and larger",
          "[figures]") {
  // The wall's letters F are of spheres 0.1 apart at z = 7.5: 8 pixels apart on the
  // canvas. Through the lens, inside its focal length, the F at the middle is upright
  // (its top bar above, its upright stroke on the left) and about twice as large.
  const Canvas canvas = RenderFigureNamed(Figures({}), "refraction-magnifying-glass");
  auto red = [&](int x, int y) {
    const Rgb8 pixel = canvas.GetPixel(x, y);
    return pixel.r > pixel.g + 80;
  };
  // The red runs along the row y = 0, through the F's middle bar ("##."), as
  // (first, last) pixels.
  auto runs = [&](int x_begin, int x_end) {
    std::vector<std::pair<int, int>> found;
    for (int x = x_begin; x < x_end; ++x) {
      if (red(x, 0) && (found.empty() || found.back().second != x - 1)) {
        found.push_back({x, x});
      } else if (red(x, 0)) {
        found.back().second = x;
      }
    }
    return found;
  };
  const auto inside = runs(-45, 45);
  REQUIRE(inside.size() == 2);  // the middle bar's two spheres
  for (const auto& [first, last] : runs(-200, -90)) {
    INFO("a sphere outside the lens from x = " << first << " to " << last);
    CHECK(last - first + 1 <= 8);
  }
  for (const auto& [first, last] : inside) {
    INFO("a sphere through the lens from x = " << first << " to " << last);
    CHECK(last - first + 1 >= 12);
  }
  const double spacing =
      (inside[1].first + inside[1].second - inside[0].first - inside[0].second) / 2.0;
  CHECK(spacing / 8 == Approx(2.2).margin(0.15));
  // Upright and not mirrored: more of the F's red above the middle and left of it.
  double x_sum = 0, y_sum = 0;
  int count = 0;
  for (int x = -45; x < 45; ++x) {
    for (int y = -45; y < 45; ++y) {
      if (red(x, y)) {
        x_sum += x;
        y_sum += y;
        ++count;
      }
    }
  }
  REQUIRE(count > 500);
  CHECK(x_sum / count < -4);
  CHECK(y_sum / count > 4);
}
