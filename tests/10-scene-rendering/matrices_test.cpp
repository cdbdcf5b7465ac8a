// Chapter 10's matrices: their entries, from the cases of 10-scene-rendering.json, and
// what they do to points (w = 1) and directions (w = 0). Chapter 11 and later keep them
// and run these tests too.
#include <catch2/catch.hpp>

#include "cases.h"
#include "matrices.h"

using Catch::Detail::Approx;

namespace {

glm::dvec4 Point4(double x, double y, double z) {
  return {x, y, z, 1};
}
glm::dvec4 Direction4(double x, double y, double z) {
  return {x, y, z, 0};
}

void CheckNear(const glm::dvec4& actual, const glm::dvec4& expected) {
  for (int i = 0; i < 4; ++i) {
    CHECK(actual[i] == Approx(expected[i]).margin(1e-12));
  }
}

}  // namespace

TEST_CASE("MakeTranslationMatrix: the cases of 10-scene-rendering.json", "[math]") {
  for (const cgfs::test::FunctionCase& c :
       cgfs::test::CasesOf("10-scene-rendering.json", "MakeTranslationMatrix")) {
    INFO(c.Describe());
    const glm::dmat4 M = MakeTranslationMatrix(cgfs::test::ToVector(c.args.at("translation")));
    CHECK_THAT(cgfs::test::AsNumbers(M), cgfs::test::MatchesCase(c));
  }
}

TEST_CASE("MakeScalingMatrix: the cases of 10-scene-rendering.json", "[math]") {
  for (const cgfs::test::FunctionCase& c :
       cgfs::test::CasesOf("10-scene-rendering.json", "MakeScalingMatrix")) {
    INFO(c.Describe());
    const glm::dmat4 M = MakeScalingMatrix(cgfs::test::ToNumber(c.args.at("scale")));
    CHECK_THAT(cgfs::test::AsNumbers(M), cgfs::test::MatchesCase(c));
  }
}

TEST_CASE("MakeOYRotationMatrix: the cases of 10-scene-rendering.json", "[math]") {
  for (const cgfs::test::FunctionCase& c :
       cgfs::test::CasesOf("10-scene-rendering.json", "MakeOYRotationMatrix")) {
    INFO(c.Describe());
    const glm::dmat4 M = MakeOYRotationMatrix(cgfs::test::ToNumber(c.args.at("degrees")));
    CHECK_THAT(cgfs::test::AsNumbers(M), cgfs::test::MatchesCase(c));
  }
}

TEST_CASE("MakeTranslationMatrix moves points, not directions", "[math]") {
  const glm::dmat4 T = MakeTranslationMatrix({1, 2, 3});
  CHECK(T * Point4(1, 1, 1) == Point4(2, 3, 4));
  CHECK(T * Direction4(1, 1, 1) == Direction4(1, 1, 1));
}

TEST_CASE("MakeScalingMatrix scales about the origin", "[math]") {
  CHECK(MakeScalingMatrix(2) * Point4(1, 2, 3) == Point4(2, 4, 6));
  CHECK(MakeScalingMatrix(0.75) * Point4(1, 1, 1) == Point4(0.75, 0.75, 0.75));
}

TEST_CASE("MakeOYRotationMatrix turns +Z towards -X, as the demos' OY does", "[math]") {
  CheckNear(MakeOYRotationMatrix(90) * Direction4(0, 0, 1), Direction4(-1, 0, 0));
  CheckNear(MakeOYRotationMatrix(90) * Direction4(1, 0, 0), Direction4(0, 0, 1));
  CheckNear(MakeOYRotationMatrix(-30) * Direction4(0, 0, 1),
            Direction4(0.5, 0, 0.8660254037844386));
  CheckNear(MakeOYRotationMatrix(37) * Direction4(0, 1, 0), Direction4(0, 1, 0));
}
