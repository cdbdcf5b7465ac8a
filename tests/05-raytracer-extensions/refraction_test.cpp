// "Refraction": Snell's law, on the cases of tests/cases/05-raytracer-extensions.json and
// by the angles themselves.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <optional>

#include "cases.h"
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

TEST_CASE("RefractRay: the cases of 05-raytracer-extensions.json", "[equations]") {
  using cgfs::test::ToNumber;
  using cgfs::test::ToVector;
  for (const cgfs::test::FunctionCase& c :
       cgfs::test::CasesOf("05-raytracer-extensions.json", "RefractRay")) {
    INFO(c.Describe());
    const std::optional<Vec3> T = RefractRay(ToVector(c.args.at("D")), ToVector(c.args.at("N")),
                                             ToNumber(c.args.at("n1")), ToNumber(c.args.at("n2")));
    CHECK_THAT(cgfs::test::AsNumbers(T), cgfs::test::MatchesCase(c));
  }
}

TEST_CASE("RefractRay: from air into water at 60 degrees, 40.628 degrees", "[equations]") {
  const Vec3 N{0, 1, 0};
  const auto T = RefractRay(Incoming(60), N, 1.0, 1.33);
  REQUIRE(T.has_value());
  CHECK(glm::length(*T) == Approx(1));
  CHECK(Degrees(std::acos(glm::dot(*T, -N))) == Approx(40.628).margin(0.0005));
  // sin 60 / sin 40.628 = 1.33 / 1.0
  CHECK(std::sin(60 * std::numbers::pi / 180) / std::sqrt(1 - T->y * T->y) == Approx(1.33));
}
