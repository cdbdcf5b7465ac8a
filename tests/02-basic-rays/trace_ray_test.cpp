// TraceRay (Listing 2-4) on its cases in tests/cases/02-basic-rays.json, and the main
// loop of chapter 2 (Listing 2-2).
#include <catch2/catch.hpp>

#include "cases.h"
#include "printing.h"
#include "raytracer.h"

using cgfs::test::IsSameImageAs;

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

TEST_CASE("RenderScene paints every pixel of the canvas", "[equations]") {
  // A non-square canvas: x and y each run over their own side. (A loop that also
  // visits a row past the canvas cannot be seen: PutPixel drops what falls off it.)
  Scene empty;
  empty.background_color = cgfs::kBlack;
  Canvas canvas(40, 30, cgfs::kWhite);
  RenderScene(empty, canvas);
  CHECK_THAT(canvas.GetImage(), IsSameImageAs(cgfs::Image(40, 30, cgfs::Rgb8{0, 0, 0})));
}
