// TraceRay (Listing 2-4) and the main loop of chapter 2 (Listing 2-2).
#include <catch2/catch.hpp>

#include "printing.h"
#include "raytracer.h"

using cgfs::test::IsSameImageAs;

TEST_CASE("TraceRay keeps the nearest root inside [t_min, t_max]", "[equations]") {
  Scene scene;
  scene.background_color = cgfs::kWhite;
  scene.spheres = {{{0, 0, 5}, 1, cgfs::kRed}, {{0, 0, 10}, 1, cgfs::kBlue}};
  CHECK(TraceRay({0, 0, 0}, {0, 0, 1}, 1, cgfs::kInf, scene) == cgfs::kRed);
  // The red sphere spans t in [4, 6]: start past it and the blue one is nearest.
  CHECK(TraceRay({0, 0, 0}, {0, 0, 1}, 6.5, cgfs::kInf, scene) == cgfs::kBlue);
  // Inside the red sphere, its far side (t = 6) is the nearest root past t_min.
  CHECK(TraceRay({0, 0, 0}, {0, 0, 1}, 5, cgfs::kInf, scene) == cgfs::kRed);
  // Closed interval: a root exactly at t_max still counts.
  CHECK(TraceRay({0, 0, 0}, {0, 0, 1}, 1, 4, scene) == cgfs::kRed);
  CHECK(TraceRay({0, 0, 0}, {0, 0, 1}, 1, 3.99, scene) == cgfs::kWhite);
  // Nothing behind the projection plane: t_min = 1 skips a sphere at t < 1.
  scene.spheres = {{{0, 0, 0.5}, 0.1, cgfs::kRed}};
  CHECK(TraceRay({0, 0, 0}, {0, 0, 1}, 1, cgfs::kInf, scene) == cgfs::kWhite);
}

TEST_CASE("RenderScene paints every pixel of the canvas exactly once", "[equations]") {
  Scene empty;
  empty.background_color = cgfs::kBlack;
  Canvas canvas(40, 30, cgfs::kWhite);
  RenderScene(empty, canvas);
  CHECK_THAT(canvas.GetImage(), IsSameImageAs(cgfs::Image(40, 30, cgfs::Rgb8{0, 0, 0})));
}
