// The chapter's figures, pixel by pixel and as whole images.
#include <catch2/catch.hpp>

#include "golden.h"
#include "printing.h"
#include "scenes.h"

using cgfs::Rgb8;
using cgfs::test::CheckAgainstGolden;
using cgfs::test::RenderFigureNamed;

TEST_CASE("pinned pixels of the diffuse figure", "[figures]") {
  const Canvas canvas = RenderFigureNamed(Figures(), "fig-3-7-diffuse");
  CHECK(canvas.GetPixel(0, -150) == Rgb8{171, 0, 0});
  CHECK(canvas.GetPixel(-250, 0) == Rgb8{0, 200, 0});
  CHECK(canvas.GetPixel(250, 0) == Rgb8{0, 0, 141});
  CHECK(canvas.GetPixel(-300, -300) == Rgb8{161, 161, 0});
  CHECK(canvas.GetPixel(100, -250) == Rgb8{181, 0, 0});
  CHECK(canvas.GetPixel(-200, -100) == Rgb8{0, 117, 0});
  CHECK(canvas.GetPixel(0, 0) == Rgb8{127, 0, 0});
  CHECK(canvas.GetPixel(0, 100) == Rgb8{255, 255, 255});
}

TEST_CASE("pinned pixels of the specular figure", "[figures]") {
  const Canvas canvas = RenderFigureNamed(Figures(), "fig-3-16-specular");
  CHECK(canvas.GetPixel(0, -150) == Rgb8{171, 0, 0});
  CHECK(canvas.GetPixel(-250, 0) == Rgb8{0, 255, 0});  // raw 296.02: clamped on write
  CHECK(canvas.GetPixel(250, 0) == Rgb8{0, 0, 141});
  CHECK(canvas.GetPixel(-300, -300) == Rgb8{161, 161, 0});
  CHECK(canvas.GetPixel(100, -250) == Rgb8{181, 0, 0});
  CHECK(canvas.GetPixel(-200, -100) == Rgb8{0, 117, 0});
  CHECK(canvas.GetPixel(0, 0) == Rgb8{127, 0, 0});
  CHECK(canvas.GetPixel(0, 100) == Rgb8{255, 255, 255});
}

TEST_CASE("the green highlight goes above 255 before it is clamped", "[figures]") {
  const Canvas canvas(600, 600);
  const Scene scene = SceneSpecular();
  const Color raw =
      TraceRay({0, 0, 0}, CanvasToViewport(-250, 0, canvas, scene.viewport), 1, cgfs::kInf, scene);
  CHECK(raw.g == Approx(296.02).margin(0.01));
}

TEST_CASE("fig-3-7-diffuse matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "fig-3-7-diffuse");
}

TEST_CASE("fig-3-16-specular matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "fig-3-16-specular");
}
