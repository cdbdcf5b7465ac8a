// The mip-level view of the crates: the level each pixel reads, against the texels per
// pixel that rays through it and its neighbours find (an independent ray caster).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "cast_uv.h"
#include "cost_checks.h"
#include "golden.h"
#include "scenes.h"

using cgfs::test::CastCameraOf;
using cgfs::test::CastSceneOf;
using cgfs::test::CastUV;
using cgfs::test::FindFigure;

namespace {

// The levels the view shows, read back from its colours: level k is the ramp's colour
// for k on its scale of 0 to 8, grey is no texture (-1); any other colour is -2.
std::vector<cgfs::Count> LevelsShown(const cgfs::Canvas& view) {
  const int above_strip = 600 - cgfs::CostStripHeight(600) - 1;
  std::vector<cgfs::Count> levels(600 * 600, -1);
  for (int row = 0; row < above_strip; ++row) {
    for (int column = 0; column < 600; ++column) {
      const cgfs::Rgb8 pixel = view.GetImage().At(column, row);
      cgfs::Count level = pixel == cgfs::kCostNothing ? -1 : -2;
      for (cgfs::Count k = 0; k <= 8; ++k) {
        if (pixel == cgfs::CostRamp(cgfs::CostPosition(static_cast<double>(k), 8))) {
          level = k;
        }
      }
      levels[row * 600 + column] = level;
    }
  }
  return levels;
}

}  // namespace

TEST_CASE("the mip-level view reads the level of the texels a pixel covers, as rays find them",
          "[cost][ray-cast]") {
  const Model crate = TexturedCube(BuildMipChain(MakeCrateTexture(256)));
  const Scene scene = SceneCrates(crate);
  const std::vector<cgfs::Figure> figures = Figures({});
  const std::vector<cgfs::Count> levels =
      LevelsShown(cgfs::test::RenderFigureNamed(figures, "crates-trilinear-mip-levels"));
  CHECK(std::count(levels.begin(), levels.end(), -2L) == 0);
  const cgfs::test::CastScene cast_scene = CastSceneOf(scene);
  const cgfs::test::CastCamera camera = CastCameraOf(scene);
  // The hit and its texture coordinates of the ray through canvas point (x, y).
  const auto cast = [&](double x, double y) {
    const glm::dvec3 D = camera.orientation * glm::dvec3(x / 600, y / 600, camera.distance);
    return cgfs::test::Cast(cast_scene, camera.position, D, 1, 1e9, true);
  };
  cgfs::Count compared = 0, agreeing = 0, untextured = 0;
  // Above the scale strip, which covers the bottom rows.
  const int lowest = -300 + cgfs::CostStripHeight(600) + 1;
  for (int y = lowest; y < 300; y += 2) {
    for (int x = -300; x < 300; x += 2) {
      const auto here = cast(x, y), right = cast(x + 1, y), up = cast(x, y + 1);
      if (!here || !right || !up || right->triangle != here->triangle ||
          up->triangle != here->triangle || right->instance != here->instance ||
          up->instance != here->instance) {
        continue;  // off the crates, or at an edge
      }
      const glm::dvec2 uv = CastUV(scene, cast_scene, *here);
      const double rho = std::max(glm::length(256.0 * (CastUV(scene, cast_scene, *right) - uv)),
                                  glm::length(256.0 * (CastUV(scene, cast_scene, *up) - uv)));
      const double level = std::clamp(std::log2(std::max(rho, 1.0)), 0.0, 8.0);
      if (std::abs(level - std::floor(level) - 0.5) < 0.05) {
        continue;  // a step or so from where the level changes
      }
      const cgfs::Count shown = levels[(299 - y) * 600 + (x + 300)];
      if (shown < 0) {
        ++untextured;  // the silhouette a pixel or two from the rays' (see below)
        continue;
      }
      ++compared;
      agreeing += shown == std::lround(level);
    }
  }
  INFO(agreeing << " of " << compared << " pixels agree; " << untextured
                << " show no texture where the rays hit a crate");
  CHECK(compared > 10000);
  // All but a row or two of pixels along the first crate's top face, a sliver a few pixels tall
  // seen almost edge-on, where the rays find that face and the rasteriser the faces
  // below it (12 pixels of these samples).
  CHECK(compared - agreeing <= compared / 1000);
  // The rasteriser's silhouettes stand a little off the rays' along the crates' lower
  // edges (the figures' own ray-cast tests bound that): few such pixels.
  CHECK(untextured < compared / 100);
  // What the view says once drawn: the levels of every pixel (those under the scale strip
  // too, which the picture hides), at most the largest it shows.
  cgfs::Count shown_total = 0;
  for (const cgfs::Count level : levels) {
    shown_total += std::max(level, cgfs::Count{0});
  }
  const std::string said =
      cgfs::test::MeasuredByFigureNamed(figures, "crates-trilinear-mip-levels");
  INFO("said: " << said << "; above the strip: " << shown_total);
  std::string digits = said.substr(0, said.find(" in all"));
  std::erase(digits, ' ');
  CHECK(std::stol(digits) >= shown_total);
  CHECK(
      said.ends_with("at most " + std::to_string(*std::max_element(levels.begin(), levels.end()))));
  CHECK(FindFigure(figures, "crates-trilinear").cost_view == "crates-trilinear-mip-levels");
}
