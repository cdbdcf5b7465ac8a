// CanvasToViewport and IntersectRaySphere, with hand-checked values.
// Chapters 3 and 4 keep both functions unchanged and run these tests too.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "printing.h"
#include "raytracer.h"

using Catch::Detail::Approx;

namespace {

const Sphere kRedSphere{{0, -1, 3}, 1, cgfs::kRed};

}  // namespace

TEST_CASE("CanvasToViewport scales pixels to the 1x1 viewport at d = 1", "[equations]") {
  const Canvas canvas(600, 600);
  const Viewport viewport;  // Vw = Vh = d = 1
  CHECK(CanvasToViewport(300, -150, canvas, viewport) == Vec3(0.5, -0.25, 1));
  CHECK(CanvasToViewport(0, 0, canvas, viewport) == Vec3(0, 0, 1));
}

TEST_CASE("CanvasToViewport: the 1x1 viewport at d = 1 gives a 53.13 degree field of view",
          "[equations]") {
  // The canvas's left edge, x = -Cw/2, looks along (-0.5, 0, 1): 26.57 degrees left of
  // straight ahead, twice that from edge to edge.
  const Canvas canvas(600, 600);
  const Vec3 edge = CanvasToViewport(-300, 0, canvas, Viewport{});
  const double fov = 2 * std::atan(-edge.x / edge.z);
  CHECK(fov * 180 / std::numbers::pi == Approx(53.13).margin(0.005));
}

TEST_CASE("IntersectRaySphere: a ray through the centre hits at both sides", "[equations]") {
  const auto [t1, t2] = IntersectRaySphere({0, 0, 0}, {0, 0, 1}, {{0, 0, 5}, 1, cgfs::kRed});
  CHECK(t1 == 6);
  CHECK(t2 == 4);
}

TEST_CASE("IntersectRaySphere: a = 10, b = -20, c = 9 against the red sphere", "[equations]") {
  const auto [t1, t2] = IntersectRaySphere({0, 0, 0}, {0, -1, 3}, kRedSphere);
  CHECK(t1 == Approx(1.3162278));
  CHECK(t2 == Approx(0.6837722));
  CHECK(t1 >= t2);
}

TEST_CASE("IntersectRaySphere: a miss returns (inf, inf)", "[equations]") {
  const auto [t1, t2] = IntersectRaySphere({0, 0, 0}, {0, 0, 1}, {{0, 2, 5}, 1, cgfs::kRed});
  CHECK(t1 == cgfs::kInf);
  CHECK(t2 == cgfs::kInf);
}

TEST_CASE("IntersectRaySphere: the central ray grazes the top of the red sphere", "[equations]") {
  // disc = 0 exactly: a tangent counts as a hit with t1 = t2 = 3 at (0, 0, 3).
  const auto [t1, t2] = IntersectRaySphere({0, 0, 0}, {0, 0, 1}, kRedSphere);
  CHECK(t1 == 3);
  CHECK(t2 == 3);
}
