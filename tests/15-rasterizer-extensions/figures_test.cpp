// The chapter's figures, pixel by pixel and as whole images.
#include <catch2/catch.hpp>

#include "golden.h"
#include "pixels.h"
#include "printing.h"
#include "scenes.h"

using cgfs::Rgb8;
using cgfs::test::ChangedPixels;
using cgfs::test::CheckAgainstGolden;
using cgfs::test::RenderFigureNamed;

TEST_CASE("figure 15-1: the normal map lights the faces that turn towards the light", "[figures]") {
  // (-22, 18) is on the left face of a bump near the centre, (-8, 18) on its right face.
  const Canvas flat = RenderFigureNamed(Figures({}), "fig-15-1a-textured-square");
  const Canvas left = RenderFigureNamed(Figures({}), "fig-15-1b-normal-map-lit-from-left");
  const Canvas right = RenderFigureNamed(Figures({}), "fig-15-1c-normal-map-lit-from-right");
  CHECK(left.GetPixel(-22, 18) == Rgb8{160, 144, 114});
  CHECK(left.GetPixel(-8, 18) ==
        Rgb8{43, 38, 30});  // ambient only: 0.2 x the tile's (214, 192, 152)
  CHECK(right.GetPixel(-22, 18) == Rgb8{43, 38, 30});
  CHECK(right.GetPixel(-8, 18) == Rgb8{159, 142, 113});
  // Without the map both points are lit alike.
  CHECK(std::abs(flat.GetPixel(-22, 18).r - flat.GetPixel(-8, 18).r) <= 2);
}

TEST_CASE("the mirror sphere shows its surroundings", "[figures]") {
  const Canvas mirrored = RenderFigureNamed(Figures({}), "environment-map");
  const Model crate = TexturedCube(*CrateTexture({}));
  Canvas plain(600, 600);
  RenderScene(SceneMirrorSphere(crate), plain);
  // The sphere's own colour is (40, 40, 40); it reflects the floor's light checker
  // below its centre and a crate (brown) above it.
  CHECK(plain.GetPixel(0, -60).r < 100);
  CHECK(mirrored.GetPixel(0, -60) == Rgb8{211, 211, 211});
  CHECK(mirrored.GetPixel(10, -80) == Rgb8{42, 32, 20});
}

TEST_CASE("both kinds of shadows fall where the light is blocked", "[figures]") {
  const Canvas none = RenderFigureNamed(Figures({}), "no-shadows");
  for (const char* name : {"stencil-shadows", "shadow-map", "shadow-map-pcf"}) {
    INFO(name);
    const Canvas shadowed = RenderFigureNamed(Figures({}), name);
    CHECK(none.GetPixel(20, -290) == Rgb8{177, 177, 177});
    CHECK(shadowed.GetPixel(20, -290) == Rgb8{40, 40, 40});             // the floor, ambient only
    CHECK(shadowed.GetPixel(-280, -160) == none.GetPixel(-280, -160));  // lit floor
    CHECK(shadowed.GetPixel(50, -200) == none.GetPixel(50, -200));      // the lit sphere
  }
}

TEST_CASE("the camera in a shadow: depth fail is right, depth pass swaps light and shadow",
          "[figures]") {
  const Canvas fail = RenderFigureNamed(Figures({}), "camera-in-shadow-depth-fail");
  const Canvas pass = RenderFigureNamed(Figures({}), "camera-in-shadow-depth-pass");
  CHECK(fail.GetPixel(0, -280) == Rgb8{40, 40, 40});     // the floor at the camera's feet
  CHECK(fail.GetPixel(0, -100) == Rgb8{200, 200, 200});  // the floor farther out, lit
  CHECK(pass.GetPixel(0, -280) == Rgb8{189, 189, 189});
  CHECK(pass.GetPixel(0, -100) == Rgb8{40, 40, 40});
  CHECK(fail.GetPixel(-120, 0).g > pass.GetPixel(-120, 0).g);  // the sphere, lit
}

TEST_CASE("fig-15-1a-textured-square matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "fig-15-1a-textured-square");
}

TEST_CASE("fig-15-1b-normal-map-lit-from-left matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "fig-15-1b-normal-map-lit-from-left");
}

TEST_CASE("fig-15-1c-normal-map-lit-from-right matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "fig-15-1c-normal-map-lit-from-right");
}

TEST_CASE("fig-15-2-normal-map matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "fig-15-2-normal-map");
}

TEST_CASE("fig-15-3a-ambient-pass matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "fig-15-3a-ambient-pass");
}

TEST_CASE("fig-15-3b-directional-pass matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "fig-15-3b-directional-pass");
}

TEST_CASE("fig-15-3c-point-pass matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "fig-15-3c-point-pass");
}

TEST_CASE("fig-15-3d-sum-of-passes matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "fig-15-3d-sum-of-passes");
}

TEST_CASE("fig-15-4-shadow-volume matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "fig-15-4-shadow-volume");
}

TEST_CASE("no-shadows matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "no-shadows");
}

TEST_CASE("stencil-shadows matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "stencil-shadows");
}

TEST_CASE("shadow-map matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "shadow-map");
}

TEST_CASE("shadow-map-pcf matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "shadow-map-pcf");
}

TEST_CASE("camera-in-shadow-depth-fail matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "camera-in-shadow-depth-fail");
}

TEST_CASE("camera-in-shadow-depth-pass matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "camera-in-shadow-depth-pass");
}

TEST_CASE("shadow-map-directional matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "shadow-map-directional");
}

TEST_CASE("environment-map matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "environment-map");
}

TEST_CASE("cube-map matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "cube-map");
}

TEST_CASE("everything matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "everything");
}

TEST_CASE("stencil-shadows-stencil-writes matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "stencil-shadows-stencil-writes");
}

TEST_CASE("shadow-map-pixels-per-entry matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "shadow-map-pixels-per-entry");
}
