// Spec §7.4: Interpolate, exactly. Every later rasterizer chapter keeps it unchanged
// and runs these tests too.
#include <catch2/catch.hpp>

#include <utility>
#include <vector>

#include "rasterizer.h"

TEST_CASE("Interpolate returns one value per integer step", "[interpolate]") {
  CHECK(Interpolate(0, 0, 4, 2) == std::vector<double>{0, 0.5, 1, 1.5, 2});
  CHECK(Interpolate(0, 10, 2, 0) == std::vector<double>{10, 5, 0});
  CHECK(Interpolate(-2, 1, 1, -5) == std::vector<double>{1, -1, -3, -5});
}

TEST_CASE("Interpolate with i0 == i1 returns [d0]", "[interpolate]") {
  CHECK(Interpolate(3, 7, 3, 9) == std::vector<double>{7});
}

TEST_CASE("Interpolate over a descending range returns nothing", "[interpolate]") {
  CHECK(Interpolate(5, 0, 3, 1).empty());
}

TEST_CASE("Interpolate does not drift: the last value is d1", "[interpolate]") {
  // Accumulating d += a would add up rounding errors over hundreds of steps.
  for (const auto& [i1, d1] : {std::pair{500, 220.0}, std::pair{440, 220.0}, std::pair{301, 7.0}}) {
    const std::vector<double> values = Interpolate(0, 0, i1, d1);
    REQUIRE(values.size() == static_cast<std::size_t>(i1 + 1));
    CHECK(values.back() == d1);
  }
}
