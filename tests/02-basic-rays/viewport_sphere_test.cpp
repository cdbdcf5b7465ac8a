// CanvasToViewport and IntersectRaySphere on their cases in tests/cases/02-basic-rays.json
// (hand-checked values, shared with the runners for other languages). Chapters 3 to 5
// keep both functions unchanged and run these tests too.
#include <catch2/catch.hpp>

#include "cases.h"
#include "printing.h"
#include "raytracer.h"

using cgfs::test::AsNumbers;
using cgfs::test::CasesOf;
using cgfs::test::FunctionCase;
using cgfs::test::MatchesCase;
using cgfs::test::ToColor;
using cgfs::test::ToNumber;
using cgfs::test::ToVector;

namespace {

Viewport ViewportOfCase(const nlohmann::json& viewport) {
  return {ToNumber(viewport.at("width")), ToNumber(viewport.at("height")),
          ToNumber(viewport.at("d"))};
}

Sphere SphereOfCase(const nlohmann::json& sphere) {
  return {ToVector(sphere.at("center")), ToNumber(sphere.at("radius")),
          ToColor(sphere.at("color"))};
}

}  // namespace

TEST_CASE("CanvasToViewport: the cases of 02-basic-rays.json", "[equations]") {
  for (const FunctionCase& c : CasesOf("02-basic-rays.json", "CanvasToViewport")) {
    INFO(c.Describe());
    const nlohmann::json& size = c.given.at("canvas");
    const Canvas canvas(size.at("width").get<int>(), size.at("height").get<int>());
    CHECK_THAT(AsNumbers(CanvasToViewport(ToNumber(c.args.at("x")), ToNumber(c.args.at("y")),
                                          canvas, ViewportOfCase(c.given.at("viewport")))),
               MatchesCase(c));
  }
}

TEST_CASE("IntersectRaySphere: the cases of 02-basic-rays.json", "[equations]") {
  for (const FunctionCase& c : CasesOf("02-basic-rays.json", "IntersectRaySphere")) {
    INFO(c.Describe());
    CHECK_THAT(AsNumbers(IntersectRaySphere(ToVector(c.args.at("O")), ToVector(c.args.at("D")),
                                            SphereOfCase(c.args.at("sphere")))),
               MatchesCase(c));
  }
}
