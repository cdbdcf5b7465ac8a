// The chapter's figures, pixel by pixel and as whole images.
#include <catch2/catch.hpp>

#include "golden.h"
#include "printing.h"
#include "scenes.h"

using cgfs::Rgb8;
using cgfs::test::CheckAgainstGolden;
using cgfs::test::RenderFigureNamed;

namespace {

constexpr Rgb8 kRed{255, 0, 0};
constexpr Rgb8 kGreen{0, 255, 0};
constexpr Rgb8 kBlue{0, 0, 255};
constexpr Rgb8 kYellow{255, 255, 0};
constexpr Rgb8 kWhite{255, 255, 255};

}  // namespace

TEST_CASE("pinned pixels of the scene with the ground sphere", "[figures]") {
  const Canvas canvas = RenderFigureNamed(Figures(), "fig-2-11-with-ground");
  CHECK(canvas.GetPixel(0, -150) == kRed);
  CHECK(canvas.GetPixel(-250, 0) == kGreen);
  CHECK(canvas.GetPixel(250, 0) == kBlue);
  CHECK(canvas.GetPixel(0, 100) == kWhite);
  CHECK(canvas.GetPixel(-300, -300) == kYellow);
  CHECK(canvas.GetPixel(-200, -100) == kGreen);
  CHECK(canvas.GetPixel(100, -250) == kRed);
  CHECK(canvas.GetPixel(0, 0) == kRed);  // the tangent ray (disc = 0) counts as a hit
}

TEST_CASE("pinned pixels of the three-sphere scene", "[figures]") {
  const Canvas canvas = RenderFigureNamed(Figures(), "fig-2-11");
  CHECK(canvas.GetPixel(0, -150) == kRed);
  CHECK(canvas.GetPixel(-250, 0) == kGreen);
  CHECK(canvas.GetPixel(250, 0) == kBlue);
  CHECK(canvas.GetPixel(0, 100) == kWhite);
  CHECK(canvas.GetPixel(-300, -300) == kWhite);  // no ground: background
  CHECK(canvas.GetPixel(0, 0) == kRed);
}

TEST_CASE("pinned pixels of the three spheres on a 600x400 canvas with a 1.5 x 1 viewport",
          "[figures]") {
  // Square pixels: 400 to a viewport unit both ways, so a pixel's ray is
  // (x / 400, y / 400, 1). Worked by hand from the discriminant of each sphere:
  // along x = 200 (towards the blue sphere's centre, (0.5, s, 1)) the blue sphere spans
  // |s| <= 0.2565, so y <= 102; the green one spans x / 400 in [-0.824, -0.243] on y = 0.
  // A y scaled by the canvas's width (600) would reach y = 153, an x scaled by its
  // height would squeeze the green sphere to x in [-220, -65].
  Scene scene = SceneThreeSpheres();
  scene.viewport = {1.5, 1, 1};
  Canvas canvas(600, 400);
  RenderScene(scene, canvas);
  CHECK(canvas.GetPixel(200, 95) == kBlue);
  CHECK(canvas.GetPixel(200, 120) == kWhite);
  CHECK(canvas.GetPixel(-280, 0) == kGreen);
  CHECK(canvas.GetPixel(-80, 0) == kWhite);
  CHECK(canvas.GetPixel(0, -150) == kRed);
}

TEST_CASE("fig-2-11 matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "fig-2-11");
}

TEST_CASE("fig-2-11-with-ground matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "fig-2-11-with-ground");
}
