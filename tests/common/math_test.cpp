// cgfs/math.h's own names for the linear algebra appendix (the rest is GLM, which has
// tests of its own).
#include <catch2/catch.hpp>

#include "cgfs/math.h"

using cgfs::Vec3;

TEST_CASE("ToCartesian: (x, y, z, w) is the point (x/w, y/w, z/w)", "[math]") {
  CHECK(cgfs::ToCartesian(glm::dvec4(1, 2, 3, 1)) == Vec3(1, 2, 3));
  CHECK(cgfs::ToCartesian(glm::dvec4(2, 4, 6, 2)) == Vec3(1, 2, 3));
  // w divides x, y and z alike, whatever its sign: not only x, not w = 1 assumed.
  CHECK(cgfs::ToCartesian(glm::dvec4(-3, -6, -9, -3)) == Vec3(1, 2, 3));
  CHECK(cgfs::ToCartesian(glm::dvec4(1, 2, 3, 4)) == Vec3(0.25, 0.5, 0.75));
}
