// The overdraw views: how many times each way of hiding surfaces writes each pixel,
// counted by the canvas (its PutPixel calls, cgfs/tally.h), against the scene's geometry and the
// figures themselves.
#include <catch2/catch.hpp>

#include <optional>
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
using cgfs::test::MeetsTriangle;
using cgfs::test::RenderFigureNamed;
using cgfs::test::Total;

namespace {

constexpr cgfs::Count kScale = 5;  // the overdraw views' shared top of the scale

// The writes RenderScene makes to each pixel of a 600x600 canvas, row by row from the top.
std::vector<cgfs::Count> Writes(const HiddenSurfaceRemoval& method) {
  Canvas canvas(600, 600);
  const cgfs::Tallying tallying(cgfs::kPixelsPut, 600, 600);
  RenderScene(SceneTransformedCubes(), canvas, method);
  return tallying.PerPixel();
}

// How many of the scene's triangles, front or back, the ray through each pixel crosses
// beyond the projection plane (t > 1): what the painter, which draws every triangle,
// should write there (MeetsTriangle, on the ray caster's triangles). With
// `which`, a number for the set of triangles crossed (a sum of a large odd number
// times each one's index plus one): where it changes, an edge passes.
struct Crossed {
  std::vector<cgfs::Count> count = std::vector<cgfs::Count>(600 * 600, 0);
  std::vector<cgfs::Count> which = std::vector<cgfs::Count>(600 * 600, 0);
};
Crossed Crossings() {
  const Scene scene = SceneTransformedCubes();
  const cgfs::test::CastScene cast = CastSceneOf(scene);
  const cgfs::test::CastCamera camera = CastCameraOf(scene);
  Crossed crossed;
  for (int y = -300; y < 300; ++y) {
    for (int x = -300; x < 300; ++x) {
      const glm::dvec3 D =
          camera.orientation * glm::dvec3(x * camera.viewport_width / 600,
                                          y * camera.viewport_height / 600, camera.distance);
      cgfs::Count count = 0, which = 0;
      for (std::size_t k = 0; k < cast.triangles.size(); ++k) {
        const std::optional<double> t = MeetsTriangle(cast.triangles[k], camera.position, D);
        if (t && *t > 1) {
          ++count;
          which += static_cast<cgfs::Count>(k + 1) * 1000003;
        }
      }
      crossed.count[(299 - y) * 600 + (x + 300)] = count;
      crossed.which[(299 - y) * 600 + (x + 300)] = which;
    }
  }
  return crossed;
}

// Whether every pixel within 2 of (column, row) has the same value: away from every
// edge, where rasterising and ray casting may disagree by a pixel (and where two
// triangles that share an edge both write it).
bool Steady(const std::vector<cgfs::Count>& counts, int column, int row) {
  for (int dr = -2; dr <= 2; ++dr) {
    for (int dc = -2; dc <= 2; ++dc) {
      const int c = column + dc, r = row + dr;
      if (c < 0 || c >= 600 || r < 0 || r >= 600 ||
          counts[r * 600 + c] != counts[row * 600 + column]) {
        return false;
      }
    }
  }
  return true;
}

bool IsWhite(const cgfs::Image& image, int i) {
  return image.At(i % 600, i / 600) == cgfs::Rgb8{255, 255, 255};
}

}  // namespace

TEST_CASE("the painter writes each pixel once for every triangle in front of it or behind",
          "[cost]") {
  const std::vector<cgfs::Count> painter =
      Writes({.draw_order = DrawOrder::kPaintersAlgorithm, .cull_back_faces = false});
  const Crossed crossings = Crossings();
  cgfs::Count compared = 0, equal = 0;
  for (int row = 0; row < 600; ++row) {
    for (int column = 0; column < 600; ++column) {
      if (Steady(crossings.which, column, row)) {
        ++compared;
        equal += painter[row * 600 + column] == crossings.count[row * 600 + column];
      }
    }
  }
  INFO(equal << " of " << compared << " pixels away from edges agree");
  CHECK(compared > 300000);
  CHECK(equal == compared);
  CHECK(Max(crossings.count) == 2);  // a closed box: a ray through it crosses it twice
  CheckDrawn(Figures(), "painters-algorithm-cubes-overdraw", painter, kScale);
}

TEST_CASE("the depth buffer writes what it shows at least once, and never more than the painter",
          "[cost]") {
  const std::vector<cgfs::Count> painter =
      Writes({.draw_order = DrawOrder::kPaintersAlgorithm, .cull_back_faces = false});
  const std::vector<cgfs::Count> depth = Writes({.cull_back_faces = false});
  const Canvas figure = RenderFigureNamed(Figures(), "fig-12-4-depth-buffer");
  cgfs::Count wrong = 0;
  for (int i = 0; i < 600 * 600; ++i) {
    wrong += (depth[i] == 0) != IsWhite(figure.GetImage(), i) || depth[i] > painter[i];
  }
  CHECK(wrong == 0);
  CHECK(Total(depth) < Total(painter));
  CheckDrawn(Figures(), "fig-12-4-depth-buffer-overdraw", depth, kScale);
}

TEST_CASE("with back faces culled, a pixel of the cubes is written once, away from edges",
          "[cost]") {
  // Two closed convex boxes apart on the screen: a ray meets one front face of one box.
  // Only on an edge two front triangles share can both write a pixel: the second when
  // its interpolated 1/z comes out strictly closer there, by rounding.
  const std::vector<cgfs::Count> culled = Writes({});
  const Crossed crossings = Crossings();
  const Canvas figure = RenderFigureNamed(Figures(), "back-face-culling");
  cgfs::Count wrong = 0, twice = 0;
  for (int i = 0; i < 600 * 600; ++i) {
    const bool shown = !IsWhite(figure.GetImage(), i);
    const bool on_edge = !Steady(crossings.which, i % 600, i / 600);
    wrong += shown ? culled[i] != 1 && !(on_edge && culled[i] == 2) : culled[i] != 0;
    twice += culled[i] == 2;
  }
  INFO(twice << " pixels on shared edges written twice");
  CHECK(wrong == 0);
  CheckDrawn(Figures(), "back-face-culling-overdraw", culled, kScale);
}

TEST_CASE("C goes from each of the three figures to its overdraw view", "[cost]") {
  for (const char* name :
       {"painters-algorithm-cubes", "fig-12-4-depth-buffer", "back-face-culling"}) {
    CHECK(FindFigure(Figures(), name).cost_view == std::string(name) + "-overdraw");
  }
}
