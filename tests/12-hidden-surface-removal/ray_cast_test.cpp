// The chapter's figures against an independent ray caster (tests/support): where the
// depth buffer decides, each pixel shows the colour of the triangle a ray through it
// meets first; where the painter or the model's order decides, it does not always.
#include <catch2/catch.hpp>

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

namespace {

// How far the figure agrees with the ray caster, on pixels more than 2 pixels from an
// edge of what they show (the rasteriser truncates toward zero: an edge can move by a
// pixel).
Agreement AgreementOf(const char* figure, Scene (*scene)()) {
  const Scene s = scene();
  const auto cast = CastCameraImage(CastSceneOf(s), CastCameraOf(s), 600, 600);
  return CompareFamilies(s, cast, RenderFigureNamed(Figures(), figure), 2);
}

}  // namespace

TEST_CASE("the depth-buffered figures show what a ray through each pixel meets first",
          "[figures][ray-cast]") {
  const struct {
    const char* figure;
    Scene (*scene)();
  } checked[] = {
      {"fig-12-4-depth-buffer", SceneTransformedCubes},
      {"back-face-culling", SceneTransformedCubes},
      {"crossing-planes-depth-inverse-z", SceneCrossingPlanes},
      {"cyclic-overlap-depth-buffer", SceneCyclicOverlap},
      {"intersecting-depth-buffer", SceneIntersectingTriangles},
      {"open-box", SceneOpenBox},
  };
  for (const auto& [figure, scene] : checked) {
    const Agreement agreement = AgreementOf(figure, scene);
    INFO(figure << ": " << Describe(agreement));
    CHECK(agreement.counted > 10000);
    CHECK(agreement.Fraction() >= 0.995);
  }
}

TEST_CASE("the painter, the model's order and the z buffer go wrong where the book says",
          "[figures][ray-cast]") {
  const struct {
    const char* figure;
    Scene (*scene)();
  } wrong[] = {
      {"fig-12-1-model-order", SceneTransformedCubes},
      {"painters-algorithm-cubes", SceneTransformedCubes},
      {"cyclic-overlap-painters", SceneCyclicOverlap},
      {"intersecting-painters", SceneIntersectingTriangles},
      {"crossing-planes-depth-z", SceneCrossingPlanes},
  };
  for (const auto& [figure, scene] : wrong) {
    const Agreement agreement = AgreementOf(figure, scene);
    INFO(figure << ": " << Describe(agreement));
    CHECK(agreement.counted - agreement.agreeing > 300);
  }
}
