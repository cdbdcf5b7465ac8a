// The card's sampler S: sky, floor, shadows and mirrors.
#include <catch2/catch.hpp>

#include "checks.h"
#include "sample.h"

using cgfs::test::CheckNear;

TEST_CASE("SkyColor: lavender at the horizon, black straight up", "[sample]") {
  CheckNear(SkyColor({1, 0, 0}), {0.7, 0.6, 1.0});
  CheckNear(SkyColor({0, 0, 1}), {0, 0, 0});
  // (1 - 0.3)^4 = 0.2401.
  CheckNear(SkyColor({0.953939, 0, 0.3}), {0.16807, 0.14406, 0.2401});
}

TEST_CASE("FloorTile: 5 x 5 tiles, white where ceil(x/5) + ceil(y/5) is even", "[sample]") {
  CheckNear(FloorTile({3, 1, 0}), {3, 3, 3});    // 1 + 1
  CheckNear(FloorTile({7, 1, 0}), {3, 1, 1});    // 2 + 1
  CheckNear(FloorTile({-1, -1, 0}), {3, 3, 3});  // 0 + 0
  CheckNear(FloorTile({-6, 1, 0}), {3, 3, 3});   // -1 + 1
  CheckNear(FloorTile({-6, -1, 0}), {3, 1, 1});  // -1 + 0: odd, though negative
  // Far beyond any int: 4e11 + 4e11 is even, and 4e11 + 1 odd.
  CheckNear(FloorTile({2e12, 2e12, 0}), {3, 3, 3});
  CheckNear(FloorTile({2e12, 5, 0}), {3, 1, 1});
}

TEST_CASE("Sample: a ray into the sky is the sky's colour, whatever the generator", "[sample]") {
  Random random(1, 0, 0);
  CheckNear(Sample({0, 50, 8}, {1, 0, 0}, random), {0.7, 0.6, 1.0});
}

TEST_CASE("Sample: the floor in the full shadow of a sphere has only its 0.1 ambient", "[sample]") {
  // (18.5, -9.5, 0) lies on the line from the light's middle (9.5, 9.5, 16) through the
  // sphere (14, 0, 8), twice as far: from there the sphere (radius 4.3°) hides the
  // whole light (1.1° each way). The tile: ceil(3.7) + ceil(-1.9) = 4 - 1, odd: red.
  for (std::uint32_t seed : {1U, 2U, 3U}) {
    Random random(seed, 0, 0);
    CheckNear(Sample({18.5, -9.5, 1}, {0, 0, -1}, random), {0.3, 0.1, 0.1});
  }
}

TEST_CASE("Sample: the lit floor is its tile times 0.2 cos + 0.1", "[sample]") {
  // At (-20, 30, 0) the light is 38.7 to 40.0 away, 16 up: cos between 0.4004 and
  // 0.4135, so the white tile (ceil(-4) + ceil(6) = 2, even) is 3 (0.2 cos + 0.1),
  // between 0.5402 and 0.5481; nothing is in the way.
  for (std::uint32_t seed : {1U, 2U, 3U}) {
    Random random(seed, 0, 0);
    const CardColor lit = Sample({-20, 30, 1}, {0, 0, -1}, random);
    CHECK(lit.x == lit.y);
    CHECK(lit.y == lit.z);
    CHECK(lit.x > 0.5402);
    CHECK(lit.x < 0.5481);
  }
}

TEST_CASE("Sample: a sphere is a mirror, and the reflections stop at the limit", "[sample]") {
  // Into the sphere (14, 0, 8) along +y: the mirror sends the ray straight back along
  // -y, level, into the sky at the horizon. The light is behind the sphere (<l, n> < 0),
  // so there is no highlight: half the horizon's colour.
  Random random(1, 0, 0);
  CheckNear(Sample({14, -5, 8}, {0, 1, 0}, random), {0.35, 0.3, 0.5});
  // At the limit the reflected ray is not followed: nothing but the (absent) highlight.
  CheckNear(Sample({14, -5, 8}, {0, 1, 0}, random, false, kMaxReflections), {0, 0, 0});
  CheckNear(Sample({14, -5, 8}, {0, 1, 0}, random, false, kMaxReflections - 1), {0.35, 0.3, 0.5});
}
