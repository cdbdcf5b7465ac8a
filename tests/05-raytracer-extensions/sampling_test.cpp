// "Subsampling" (approximate, compared under a tolerance) and "Supersampling".
#include <catch2/catch.hpp>

#include "golden.h"
#include "printing.h"
#include "sampling.h"
#include "scenes.h"

using cgfs::Rgb8;
using cgfs::test::IsSameImageAs;
using cgfs::test::RenderFigureNamed;

TEST_CASE("RenderSceneSubsampled: Figure 5-1 within the stated tolerance of the full render",
          "[sampling]") {
  // The tolerance the chapter's README states: at most 1% of the pixels differ, and
  // the traced pixels (even x and y) are exact. (Here none differ at all: Figure 5-1
  // has nothing thinner than two pixels; the wires below show what can go wrong.)
  Canvas full(600, 600);
  RenderScene(SceneCamera(), 3, full, AllOptimizations());
  Canvas approximate(600, 600);
  RenderSceneSubsampled(SceneCamera(), 3, approximate, AllOptimizations());
  long differing = 0;
  for (int x = -300; x < 300; ++x) {
    for (int y = -300; y < 300; ++y) {
      const bool traced = (x + 300) % 2 == 0 && (y + 300) % 2 == 0;
      if (traced) {
        REQUIRE(approximate.GetPixel(x, y) == full.GetPixel(x, y));
      }
      differing += approximate.GetPixel(x, y) != full.GetPixel(x, y);
    }
  }
  CHECK(differing <= 600 * 600 / 100);
}

TEST_CASE("RenderSceneSubsampled loses the wires under two pixels wide", "[sampling]") {
  const Canvas full = RenderFigureNamed(Figures({}), "thin-wires");
  const Canvas approximate = RenderFigureNamed(Figures({}), "subsampling-thin-wires");
  // Along one row, count the black pixels of each wire: the thinnest ones lose
  // pixels where they cross a column that was skipped.
  long black_full = 0;
  long black_subsampled = 0;
  for (int y = -200; y < 200; ++y) {
    for (int x = -300; x < -150; ++x) {  // the three thinnest wires
      black_full += full.GetPixel(x, y) == Rgb8{0, 0, 0};
      black_subsampled += approximate.GetPixel(x, y) == Rgb8{0, 0, 0};
    }
  }
  INFO("black pixels: " << black_full << " traced, " << black_subsampled << " subsampled");
  CHECK(black_full > 400);
  CHECK(black_subsampled < black_full * 3 / 4);
}

TEST_CASE("RenderSceneSupersampled: one ray per pixel is RenderScene", "[sampling]") {
  Canvas plain(64, 64);
  RenderScene(SceneCamera(), 3, plain, AllOptimizations());
  Canvas one(64, 64);
  RenderSceneSupersampled(SceneCamera(), 3, 1, one, AllOptimizations());
  CHECK_THAT(one.GetImage(), IsSameImageAs(plain.GetImage()));
}

TEST_CASE("RenderSceneSupersampled: edges get colours in between", "[sampling]") {
  // Across the top edge of the green sphere in Figure 5-1, one ray per pixel jumps
  // from black to green; sixteen rays put pixels in between.
  const Canvas one = RenderFigureNamed(Figures({}), "fig-5-1-camera");
  const Canvas sixteen = RenderFigureNamed(Figures({}), "supersampling-16");
  int between_one = 0;
  int between_sixteen = 0;
  for (int y = 60; y < 120; ++y) {
    const int g1 = one.GetPixel(-150, y).g;
    const int g16 = sixteen.GetPixel(-150, y).g;
    between_one += g1 > 0 && g1 < 40;
    between_sixteen += g16 > 0 && g16 < 40;
  }
  CHECK(between_sixteen > between_one);
}

TEST_CASE("RenderSceneAdaptive subdivides edges only", "[sampling]") {
  Canvas canvas(600, 600);
  const long subdivided = RenderSceneAdaptive(SceneCamera(), 3, canvas, AllOptimizations());
  CHECK(subdivided > 1000);            // every outline
  CHECK(subdivided < 600 * 600 / 10);  // but not the smooth insides
}
