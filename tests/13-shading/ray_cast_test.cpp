// The chapter's figures against an independent ray caster (tests/support): each
// pixel, away from edges, shows the colour of the model a ray through it meets first
// (light scales a colour, so its family stays: red, green, yellow...).
#include <catch2/catch.hpp>

#include <string>

#include "figure_checks.h"
#include "golden.h"
#include "scenes.h"

using cgfs::test::Agreement;
using cgfs::test::CastCameraImage;
using cgfs::test::CastCameraOf;
using cgfs::test::CastSceneOf;
using cgfs::test::CompareFamilies;
using cgfs::test::Describe;
using cgfs::test::RenderFigureNamed;

TEST_CASE("every figure shows the model a ray through each pixel meets first",
          "[figures][ray-cast]") {
  const Scene shading = SceneShading();
  const Scene close_light = SceneCloseLight();
  const Scene spheres = SceneRaytracerSpheres();
  const auto cast_shading = CastCameraImage(CastSceneOf(shading), CastCameraOf(shading), 600, 600);
  const auto cast_close =
      CastCameraImage(CastSceneOf(close_light), CastCameraOf(close_light), 600, 600);
  const auto cast_spheres = CastCameraImage(CastSceneOf(spheres), CastCameraOf(spheres), 600, 600);
  for (const cgfs::Figure& figure : Figures()) {
    const Canvas drawn = RenderFigureNamed(Figures(), figure.name);
    const bool close = figure.name.find("close-light") != std::string::npos;
    const bool ray_tracer = figure.name == "fig-13-11-raytracer-spheres";
    const Agreement agreement = close        ? CompareFamilies(close_light, cast_close, drawn, 2)
                                : ray_tracer ? CompareFamilies(spheres, cast_spheres, drawn, 2)
                                             : CompareFamilies(shading, cast_shading, drawn, 2);
    INFO(figure.name << ": " << Describe(agreement));
    CHECK(agreement.counted > 20000);
    CHECK(agreement.Fraction() >= 0.995);
  }
}
