// ComputeLighting on its cases in tests/cases/03-light.json (hand-checked values, shared
// with the runners for other languages). The scenes have no spheres, so chapter 4's
// shadow rays find nothing and it runs these tests unchanged, as does chapter 5.
#include <catch2/catch.hpp>

#include "cases.h"
#include "light_of_case.h"
#include "printing.h"
#include "raytracer.h"

TEST_CASE("ComputeLighting: the cases of 03-light.json", "[equations]") {
  using cgfs::test::ToVector;
  for (const cgfs::test::FunctionCase& c :
       cgfs::test::CasesOf("03-light.json", "ComputeLighting")) {
    INFO(c.Describe());
    Scene scene;
    for (const nlohmann::json& light : c.given.at("scene").at("lights")) {
      scene.lights.push_back(LightOfCase(light));
    }
    const double i =
        ComputeLighting(ToVector(c.args.at("P")), ToVector(c.args.at("N")),
                        ToVector(c.args.at("V")), cgfs::test::ToNumber(c.args.at("s")), scene);
    CHECK_THAT(cgfs::test::AsNumbers(i), cgfs::test::MatchesCase(c));
  }
}
