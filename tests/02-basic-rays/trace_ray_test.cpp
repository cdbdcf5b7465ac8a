// TraceRay (Listing 2-4) on its cases in tests/cases/02-basic-rays.json, and the main
// loop of chapter 2 (Listing 2-2).
#include <catch2/catch.hpp>

#include "cases.h"
#include "printing.h"
#include "raytracer.h"
#include "render_loops.h"

namespace {

Scene SceneOfTraceRayCase(const nlohmann::json& given) {
  const nlohmann::json& scene = given.at("scene");
  Scene built;
  built.background_color = cgfs::test::ToColor(scene.at("background_color"));
  for (const nlohmann::json& sphere : scene.at("spheres")) {
    built.spheres.push_back({cgfs::test::ToVector(sphere.at("center")),
                             cgfs::test::ToNumber(sphere.at("radius")),
                             cgfs::test::ToColor(sphere.at("color"))});
  }
  return built;
}

}  // namespace

TEST_CASE("TraceRay: the cases of 02-basic-rays.json", "[equations]") {
  using cgfs::test::ToNumber;
  using cgfs::test::ToVector;
  for (const cgfs::test::FunctionCase& c : cgfs::test::CasesOf("02-basic-rays.json", "TraceRay")) {
    INFO(c.Describe());
    const Color color =
        TraceRay(ToVector(c.args.at("O")), ToVector(c.args.at("D")), ToNumber(c.args.at("t_min")),
                 ToNumber(c.args.at("t_max")), SceneOfTraceRayCase(c.given));
    CHECK_THAT(cgfs::test::AsNumbers(color), cgfs::test::MatchesCase(c));
  }
}

TEST_CASE("RenderScene paints every pixel of the canvas, one ray each, Cw x Ch rays",
          "[equations]") {
  Scene empty;
  empty.background_color = cgfs::kBlack;
  cgfs::test::CheckPaintsEveryPixelOnce([&](Canvas& canvas) { RenderScene(empty, canvas); });
}
