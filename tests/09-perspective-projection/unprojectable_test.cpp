// Before clipping (chapters 9 and 10), ProjectVertex refuses what it cannot project.
#include <catch2/catch.hpp>

#include "rasterizer.h"

TEST_CASE("ProjectVertex refuses points in front of the projection plane", "[projection]") {
  const Canvas canvas(600, 600);
  CHECK_FALSE(ProjectVertex({1, 1, 0}, canvas, Viewport{}));   // would divide by zero
  CHECK_FALSE(ProjectVertex({1, 1, -5}, canvas, Viewport{}));  // behind the camera
  CHECK_FALSE(
      ProjectVertex({1, 1, 1e-300}, canvas, Viewport{}));  // would be astronomically far out
  CHECK_FALSE(ProjectVertex({1, 1, 0.999}, canvas, Viewport{}));
  CHECK(ProjectVertex({0.5, 0.5, 1}, canvas, Viewport{}) == Point{300, 300});  // on the plane
}
