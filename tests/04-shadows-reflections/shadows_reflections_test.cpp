// ClosestIntersection, ReflectRay, ComputeLighting with shadows and the recursive
// TraceRay on their cases in tests/cases/04-shadows-reflections.json (hand-checked
// values, shared with the runners for other languages); and the main loop.
#include <catch2/catch.hpp>

#include <vector>

#include "../03-light/light_of_case.h"
#include "cases.h"
#include "printing.h"
#include "render_loops.h"
#include "scenes.h"

namespace {

// The scene of a case: its spheres (matte and not reflective unless given), lights and
// background.
Scene SceneOfShadowCase(const nlohmann::json& given) {
  using cgfs::test::ToColor;
  using cgfs::test::ToNumber;
  const nlohmann::json& scene = given.at("scene");
  Scene built;
  built.background_color = ToColor(scene.value("background_color", nlohmann::json({0, 0, 0})));
  for (const nlohmann::json& sphere : scene.at("spheres")) {
    built.spheres.push_back({cgfs::test::ToVector(sphere.at("center")),
                             ToNumber(sphere.at("radius")), ToColor(sphere.at("color")),
                             ToNumber(sphere.value("specular", nlohmann::json(-1))),
                             ToNumber(sphere.value("reflective", nlohmann::json(0)))});
  }
  for (const nlohmann::json& light : scene.value("lights", nlohmann::json::array())) {
    built.lights.push_back(LightOfCase(light));
  }
  return built;
}

}  // namespace

TEST_CASE("ClosestIntersection: the cases of 04-shadows-reflections.json", "[equations]") {
  using cgfs::test::ToNumber;
  using cgfs::test::ToVector;
  for (const cgfs::test::FunctionCase& c :
       cgfs::test::CasesOf("04-shadows-reflections.json", "ClosestIntersection")) {
    INFO(c.Describe());
    const Scene scene = SceneOfShadowCase(c.given);
    const auto [sphere, t] =
        ClosestIntersection(ToVector(c.args.at("O")), ToVector(c.args.at("D")),
                            ToNumber(c.args.at("t_min")), ToNumber(c.args.at("t_max")), scene);
    // The sphere by its index in the scene, -1 for none.
    const double index =
        sphere == nullptr ? -1 : static_cast<double>(sphere - scene.spheres.data());
    CHECK_THAT((std::vector<double>{index, t}), cgfs::test::MatchesCase(c));
  }
}

TEST_CASE("ReflectRay: the cases of 04-shadows-reflections.json", "[equations]") {
  using cgfs::test::ToVector;
  for (const cgfs::test::FunctionCase& c :
       cgfs::test::CasesOf("04-shadows-reflections.json", "ReflectRay")) {
    INFO(c.Describe());
    CHECK_THAT(
        cgfs::test::AsNumbers(ReflectRay(ToVector(c.args.at("R")), ToVector(c.args.at("N")))),
        cgfs::test::MatchesCase(c));
  }
}

TEST_CASE("ComputeLighting: the cases of 04-shadows-reflections.json", "[equations]") {
  using cgfs::test::ToVector;
  for (const cgfs::test::FunctionCase& c :
       cgfs::test::CasesOf("04-shadows-reflections.json", "ComputeLighting")) {
    INFO(c.Describe());
    const double i = ComputeLighting(ToVector(c.args.at("P")), ToVector(c.args.at("N")),
                                     ToVector(c.args.at("V")), cgfs::test::ToNumber(c.args.at("s")),
                                     SceneOfShadowCase(c.given));
    CHECK_THAT(cgfs::test::AsNumbers(i), cgfs::test::MatchesCase(c));
  }
}

TEST_CASE("TraceRay: the cases of 04-shadows-reflections.json", "[equations]") {
  using cgfs::test::ToNumber;
  using cgfs::test::ToVector;
  for (const cgfs::test::FunctionCase& c :
       cgfs::test::CasesOf("04-shadows-reflections.json", "TraceRay")) {
    INFO(c.Describe());
    const Color color = TraceRay(ToVector(c.args.at("O")), ToVector(c.args.at("D")),
                                 ToNumber(c.args.at("t_min")), ToNumber(c.args.at("t_max")),
                                 static_cast<int>(ToNumber(c.args.at("recursion_depth"))),
                                 SceneOfShadowCase(c.given));
    CHECK_THAT(cgfs::test::AsNumbers(color), cgfs::test::MatchesCase(c));
  }
}

TEST_CASE("RenderScene paints every pixel of the canvas, one ray each, Cw x Ch rays",
          "[equations]") {
  Scene empty;
  empty.background_color = cgfs::kBlack;
  cgfs::test::CheckPaintsEveryPixelOnce(
      [&](Canvas& canvas) { RenderScene(empty, kDefaultRecursionDepth, canvas); });
}
