// "Refraction": Snell's law.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "checks.h"
#include "printing.h"
#include "refraction.h"

using Catch::Detail::Approx;
using cgfs::test::CheckNear;

namespace {

double Degrees(double radians) {
  return radians * 180 / std::numbers::pi;
}

// A ray going down onto the plane y = 0 at `degrees` from its normal.
Vec3 Incoming(double degrees) {
  const double a = degrees * std::numbers::pi / 180;
  return {std::sin(a), -std::cos(a), 0};
}

}  // namespace

TEST_CASE("RefractRay: from air into water at 60 degrees, 40.628 degrees", "[equations]") {
  const Vec3 N{0, 1, 0};
  const auto T = RefractRay(Incoming(60), N, 1.0, 1.33);
  REQUIRE(T.has_value());
  CHECK(glm::length(*T) == Approx(1));
  CHECK(Degrees(std::acos(glm::dot(*T, -N))) == Approx(40.628).margin(0.0005));
  // sin 60 / sin 40.628 = 1.33 / 1.0
  CHECK(std::sin(60 * std::numbers::pi / 180) / std::sqrt(1 - T->y * T->y) == Approx(1.33));
}

TEST_CASE("RefractRay: straight through along the normal, whatever the indices", "[equations]") {
  CheckNear(*RefractRay({0, -2, 0}, {0, 1, 0}, 1.0, 1.5), {0, -1, 0});
}

TEST_CASE("RefractRay: the same index does not bend the ray", "[equations]") {
  CheckNear(*RefractRay(Incoming(35), {0, 1, 0}, 1.5, 1.5), Incoming(35));
}

TEST_CASE("RefractRay: total internal reflection past the critical angle", "[equations]") {
  // From water into air the critical angle is asin(1 / 1.33) = 48.75 degrees.
  CHECK(RefractRay(Incoming(48), {0, 1, 0}, 1.33, 1.0).has_value());
  CHECK_FALSE(RefractRay(Incoming(49), {0, 1, 0}, 1.33, 1.0).has_value());
  CHECK_FALSE(RefractRay(Incoming(60), {0, 1, 0}, 1.33, 1.0).has_value());
}
