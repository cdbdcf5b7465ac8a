// The chapter's figures, pixel by pixel and as whole images.
#include <catch2/catch.hpp>

#include "golden.h"
#include "printing.h"
#include "scenes.h"

using cgfs::Rgb8;
using cgfs::test::CheckAgainstGolden;
using cgfs::test::RenderFigureNamed;

TEST_CASE("pinned pixels of the transformed cubes", "[figures]") {
  const Canvas canvas = RenderFigureNamed(Figures(), "fig-10-10");
  // Vertices are where the matrices of Listing 10-5 put them; some edge ends there.
  CHECK(canvas.GetPixel(-91, -24) != Rgb8{255, 255, 255});
  CHECK(canvas.GetPixel(-218, -258) != Rgb8{255, 255, 255});
  CHECK(canvas.GetPixel(102, 274) != Rgb8{255, 255, 255});
  CHECK(canvas.GetPixel(-42, 217) != Rgb8{255, 255, 255});
  CHECK(canvas.GetPixel(0, 0) == Rgb8{255, 255, 255});
  CHECK(canvas.GetPixel(250, -250) == Rgb8{255, 255, 255});
}

TEST_CASE("pinned pixels of the moved cube", "[figures]") {
  const Canvas canvas = RenderFigureNamed(Figures(), "fig-10-2");
  CHECK(canvas.GetPixel(-37, 75) != Rgb8{255, 255, 255});     // vertex 0
  CHECK(canvas.GetPixel(-250, -100) != Rgb8{255, 255, 255});  // vertex 6
  CHECK(canvas.GetPixel(100, 100) == Rgb8{255, 255, 255});
}

TEST_CASE("fig-10-2 matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "fig-10-2");
}

TEST_CASE("fig-10-3 matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "fig-10-3");
}

TEST_CASE("fig-10-10 matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "fig-10-10");
}
