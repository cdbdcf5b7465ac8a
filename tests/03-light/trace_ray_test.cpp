// TraceRay (Listing 3-3), which lights what it hits, on its cases in
// tests/cases/03-light.json; and the main loop.
#include <catch2/catch.hpp>

#include "cases.h"
#include "light_of_case.h"
#include "printing.h"
#include "raytracer.h"
#include "render_loops.h"

namespace {

// The scene of a TraceRay case: its spheres (matte unless "specular" is given), its
// lights and background.
Scene SceneOfLitCase(const nlohmann::json& given) {
  using cgfs::test::ToColor;
  using cgfs::test::ToNumber;
  const nlohmann::json& scene = given.at("scene");
  Scene built;
  built.background_color = ToColor(scene.at("background_color"));
  for (const nlohmann::json& sphere : scene.at("spheres")) {
    built.spheres.push_back({cgfs::test::ToVector(sphere.at("center")),
                             ToNumber(sphere.at("radius")), ToColor(sphere.at("color")),
                             ToNumber(sphere.value("specular", nlohmann::json(-1)))});
  }
  for (const nlohmann::json& light : scene.at("lights")) {
    built.lights.push_back(LightOfCase(light));
  }
  return built;
}

}  // namespace

TEST_CASE("TraceRay: the cases of 03-light.json", "[equations]") {
  using cgfs::test::ToNumber;
  using cgfs::test::ToVector;
  for (const cgfs::test::FunctionCase& c : cgfs::test::CasesOf("03-light.json", "TraceRay")) {
    INFO(c.Describe());
    const Color color =
        TraceRay(ToVector(c.args.at("O")), ToVector(c.args.at("D")), ToNumber(c.args.at("t_min")),
                 ToNumber(c.args.at("t_max")), SceneOfLitCase(c.given));
    CHECK_THAT(cgfs::test::AsNumbers(color), cgfs::test::MatchesCase(c));
  }
}

TEST_CASE("RenderScene paints every pixel of the canvas, one ray each, Cw x Ch rays",
          "[equations]") {
  Scene empty;
  empty.background_color = cgfs::kBlack;
  cgfs::test::CheckPaintsEveryPixelOnce([&](Canvas& canvas) { RenderScene(empty, canvas); });
}
