// The shadow map's resolution view: the entry each pixel's lookup reads
// (kShadowMapEntries, recorded per pixel through the tally, cgfs/tally.h), against the
// points an independent ray caster finds (ShadowMapEntry on a hand-made map:
// shadow_mapping_test.cpp).
#include <catch2/catch.hpp>

#include <algorithm>
#include <utility>
#include <vector>

#include "cost_checks.h"
#include "golden.h"
#include "ray_caster.h"
#include "scenes.h"

using cgfs::test::CastCameraOf;
using cgfs::test::CastSceneOf;
using cgfs::test::CheckDrawn;
using cgfs::test::FindFigure;
using cgfs::test::Max;
using cgfs::test::Total;

TEST_CASE("each pixel reads the entry of the point a ray through it finds, away from edges",
          "[cost][ray-cast]") {
  const Scene scene = SceneShadows();
  Canvas canvas(600, 600);
  Extensions extensions;
  extensions.shadows = Shadows::kShadowMaps;
  std::vector<cgfs::Count> entries;
  {
    const cgfs::Tallying tallying(kShadowMapEntries, 600, 600, -1);
    RenderScene(scene, canvas, {}, extensions);
    entries = tallying.PerPixel();
  }
  const ShadowMap map = RenderShadowMap(scene, scene.lights.back(), extensions.shadow_mapping);

  // The entry of the point the ray through canvas point (x, y) hits (-1: nothing), and
  // the triangle it is on.
  const cgfs::test::CastScene cast = CastSceneOf(scene);
  const cgfs::test::CastCamera camera = CastCameraOf(scene);
  const auto entry_at = [&](double x, double y) -> std::pair<cgfs::Count, cgfs::Count> {
    const glm::dvec3 D = camera.orientation * glm::dvec3(x / 600, y / 600, camera.distance);
    const auto hit = cgfs::test::Cast(cast, camera.position, D, 1, 1e9, true);
    if (!hit) {
      return {-1, -1};
    }
    return {ShadowMapEntry(map, hit->point).value_or(-1), hit->instance * 100000 + hit->triangle};
  };
  cgfs::Count compared = 0, agreeing = 0;
  for (int y = -297; y < 300; y += 3) {
    for (int x = -297; x < 300; x += 3) {
      const auto here = entry_at(x, y);
      bool steady = here.first >= 0;
      for (const auto& [dx, dy] : {std::pair{-1.5, -1.5}, {1.5, -1.5}, {-1.5, 1.5}, {1.5, 1.5}}) {
        steady = steady && entry_at(x + dx, y + dy) == here;
      }
      if (steady) {
        ++compared;
        agreeing += entries[(299 - y) * 600 + (x + 300)] == here.first;
      }
    }
  }
  INFO(agreeing << " of " << compared << " pixels inside one entry's footprint agree");
  CHECK(compared > 1000);
  CHECK(agreeing == compared);

  // The view: each pixel, the number of pixels that read its entry.
  const std::vector<cgfs::Count> shared = PixelsSharingEntry(entries);
  const std::vector<cgfs::Figure> figures = Figures({});
  CheckDrawn(figures, "shadow-map-pixels-per-entry", shared, 404);
  CHECK(FindFigure(figures, "shadow-map").cost_view == "shadow-map-pixels-per-entry");
}

TEST_CASE("PixelsSharingEntry: each pixel, how many pixels read its entry", "[cost]") {
  CHECK(PixelsSharingEntry({5, 5, -1, 7, 5}) == std::vector<cgfs::Count>{3, 3, -1, 1, 3});
  CHECK(PixelsSharingEntry({}).empty());
}
