// Listing 5-1: the camera.
#include <catch2/catch.hpp>

#include "cgfs/image_io.h"
#include "checks.h"
#include "golden.h"
#include "printing.h"
#include "scenes.h"

using cgfs::Rgb8;
using cgfs::test::CheckNear;
using cgfs::test::GoldenFile;
using cgfs::test::IsSameImageAs;
using cgfs::test::RenderFigureNamed;

TEST_CASE("CameraRayDirection turns the chapter-2 direction with the camera", "[equations]") {
  const Canvas canvas(600, 600);
  const Scene scene = SceneCamera();
  // The centre of the viewport, (0, 0, 1), turned 45 degrees about Y: towards -X and +Z.
  CheckNear(CameraRayDirection(0, 0, canvas, scene), {-0.7071, 0, 0.7071});
  // Y is the axis of the turn: the top of the viewport keeps its height.
  CheckNear(CameraRayDirection(0, 300, canvas, scene), {-0.7071, 0.5, 0.7071});
  // The default camera leaves directions as they are.
  const Scene plain = SceneReflections();
  CHECK(CameraRayDirection(150, -75, canvas, plain) ==
        CanvasToViewport(150, -75, canvas, plain.viewport));
}

TEST_CASE("pinned pixels of Figure 5-1, the camera at (3, 0, 1) turned 45 degrees", "[figures]") {
  const Canvas canvas = RenderFigureNamed(Figures({}), "fig-5-1-camera");
  CHECK(canvas.GetPixel(0, -150) == Rgb8{90, 4, 9});
  CHECK(canvas.GetPixel(-250, 0) == Rgb8{0, 94, 0});
  CHECK(canvas.GetPixel(250, 0) == Rgb8{0, 0, 135});
  CHECK(canvas.GetPixel(-200, -100) == Rgb8{163, 0, 0});
  CHECK(canvas.GetPixel(100, -250) == Rgb8{68, 68, 0});
  CHECK(canvas.GetPixel(0, 0) == Rgb8{0, 0, 0});
  CHECK(canvas.GetPixel(0, 100) == Rgb8{0, 0, 0});
}

TEST_CASE("RenderScene with the camera at the origin draws chapter 4's Figure 4-8 exactly",
          "[figures]") {
  // Everything the chapter adds (objects behind an interface, the camera, the
  // switches) leaves the old picture as it was, byte for byte.
  Canvas canvas(600, 600);
  RenderScene(SceneReflections(), 3, canvas, AllOptimizations());
  CHECK_THAT(
      canvas.GetImage(),
      IsSameImageAs(cgfs::ReadImage(GoldenFile("04-shadows-reflections", "fig-4-8-reflections"))));
}
