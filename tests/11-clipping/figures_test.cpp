// The chapter's figures, as whole images.
#include <catch2/catch.hpp>

#include "golden.h"
#include "printing.h"
#include "scenes.h"

using cgfs::Rgb8;
using cgfs::test::CheckAgainstGolden;
using cgfs::test::IsSameImageAs;
using cgfs::test::RenderFigureNamed;

TEST_CASE("the rejected cube leaves the picture of figure 10-10 unchanged", "[figures]") {
  Canvas without(600, 600);
  RenderScene(SceneTransformedCubes(), without);
  CHECK_THAT(RenderFigureNamed(Figures(), "clipped-scene").GetImage(),
             IsSameImageAs(without.GetImage()));
}

TEST_CASE("pinned pixels of the clipped scene", "[figures]") {
  const Canvas canvas = RenderFigureNamed(Figures(), "clipped-scene");
  CHECK(canvas.GetPixel(-91, -24) != Rgb8{255, 255, 255});  // instance A, vertex 0
  CHECK(canvas.GetPixel(102, 274) != Rgb8{255, 255, 255});  // instance B, vertex 0
  CHECK(canvas.GetPixel(0, 0) == Rgb8{255, 255, 255});
}

TEST_CASE("clipped-scene matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "clipped-scene");
}

TEST_CASE("near-plane-cut matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "near-plane-cut");
}
