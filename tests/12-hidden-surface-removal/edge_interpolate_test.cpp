// "Depth Buffering": the depth carried along a triangle's edges as lists, as the book
// writes it. Chapter 13 walks triangles without the lists (triangle_walker.h), so
// this test is chapter 12's alone.
#include <catch2/catch.hpp>

#include <vector>

#include "scenes.h"

TEST_CASE("EdgeInterpolate: the long side and the two short sides joined", "[depth]") {
  const auto [v02, v012] = EdgeInterpolate(0, 0, 2, 2, 4, 0);
  CHECK(v02 == std::vector<double>{0, 0, 0, 0, 0});
  CHECK(v012 == std::vector<double>{0, 1, 2, 1, 0});  // the value at y1 once
  // A flat top: y1 == y2.
  const auto [w02, w012] = EdgeInterpolate(0, 1, 2, 3, 2, 5);
  CHECK(w02 == std::vector<double>{1, 3, 5});
  CHECK(w012 == std::vector<double>{1, 2, 3});
}
