// The stencil-writes view: the writes the shadow volumes make per pixel, counted where
// the stencil buffer writes (kStencilWrites, cgfs/tally.h), against the volumes' faces a ray
// through the pixel crosses behind the surface it shows (depth fail), found by ray casting.
#include <catch2/catch.hpp>

#include <cmath>
#include <optional>
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
using cgfs::test::MeetsTriangle;
using cgfs::test::Total;

namespace {

constexpr cgfs::Count kScale = 20;  // the top of the view's scale

// The stencil's writes per pixel as RenderScene draws the shadows scene at 600x600.
std::vector<cgfs::Count> StencilWrites(const Scene& scene) {
  Canvas canvas(600, 600);
  Extensions extensions;
  extensions.shadows = Shadows::kShadowVolumes;
  const cgfs::Tallying tallying(kStencilWrites, 600, 600);
  RenderScene(scene, canvas, {}, extensions);
  return tallying.PerPixel();
}

// Each closed instance's shadow volume for `light`, built from the instance placed in
// world space (as the ray caster places it).
std::vector<Model> WorldVolumes(const Scene& scene, const Light& light) {
  std::vector<Model> volumes;
  for (const Instance& I : scene.instances) {
    if (!I.model->closed) {
      continue;
    }
    Model placed = *I.model;
    const glm::dmat3 rotation(I.transform.rotation);
    for (Vec3& v : placed.vertices) {
      v = rotation * (v * I.transform.scale) + I.transform.translation;
    }
    volumes.push_back(BuildShadowVolume(placed, light));
  }
  return volumes;
}

// How many of the volumes' triangles the ray through canvas point (x, y) crosses beyond
// the surface it shows (MeetsTriangle), and a number for which ones and for that
// surface: where it changes, an edge passes.
// `dark_side`: the surface is an occluder's side away from the light, where its
// volume's near cap lies on it, at the same depth (see BuildShadowVolume).
struct Crossing {
  cgfs::Count count = 0;
  cgfs::Count which = 0;
  bool dark_side = false;
};
Crossing VolumeCrossing(const cgfs::test::CastScene& cast, const cgfs::test::CastCamera& camera,
                        const std::vector<Model>& volumes, const Light& light, double x, double y) {
  const glm::dvec3 D =
      camera.orientation * glm::dvec3(x * camera.viewport_width / 600,
                                      y * camera.viewport_height / 600, camera.distance);
  const auto surface = cgfs::test::Cast(cast, camera.position, D, 1, 1e9, true);
  const double t_surface = surface ? surface->t : INFINITY;
  Crossing crossing{0, surface ? surface->instance * 7919 + surface->triangle : -1};
  crossing.dark_side =
      surface &&
      cast.triangles[cast.instances[static_cast<std::size_t>(surface->instance)].first +
                     static_cast<std::size_t>(surface->triangle)]
          .closed &&
      glm::dot(surface->normal, light.position - surface->point) <= 0;
  cgfs::Count k = 0;
  for (const Model& volume : volumes) {
    for (const Triangle& T : volume.triangles) {
      ++k;
      const auto corner = [&](int c) { return volume.vertices[static_cast<std::size_t>(T.v[c])]; };
      const std::optional<double> t =
          MeetsTriangle({corner(0), corner(1), corner(2)}, camera.position, D);
      if (t && *t > 1 && *t > t_surface) {
        ++crossing.count;
        crossing.which += k * 1000003;
      }
    }
  }
  return crossing;
}

}  // namespace

TEST_CASE("the stencil writes each pixel once for every volume face behind what it shows",
          "[cost][ray-cast]") {
  const Scene scene = SceneShadows();
  const std::vector<cgfs::Count> writes = StencilWrites(scene);
  const cgfs::test::CastScene cast = CastSceneOf(scene);
  const cgfs::test::CastCamera camera = CastCameraOf(scene);
  const Light& light = scene.lights.back();  // the point light
  const std::vector<Model> volumes = WorldVolumes(scene, light);
  // Every sixth pixel each way (ray casting every volume face is slow), away from
  // edges: where the rays two and a half pixels around it cross the same faces
  // beyond the same surface triangle.
  cgfs::Count compared = 0, equal = 0, dark_side = 0;
  for (int y = -297; y < 300; y += 6) {
    for (int x = -297; x < 300; x += 6) {
      const Crossing here = VolumeCrossing(cast, camera, volumes, light, x, y);
      bool steady = true;
      for (const auto& [dx, dy] : {std::pair{-2.5, -2.5}, {2.5, -2.5}, {-2.5, 2.5}, {2.5, 2.5}}) {
        steady = steady &&
                 VolumeCrossing(cast, camera, volumes, light, x + dx, y + dy).which == here.which;
      }
      if (steady) {
        ++compared;
        const cgfs::Count written = writes[(299 - y) * 600 + (x + 300)];
        // On a dark side the cap is written or not as the depth test's rounding
        // decides, pixel by pixel; it changes nothing (it adds and takes away alike).
        equal += written == here.count || (here.dark_side && written == here.count + 1);
        dark_side += here.dark_side;
      }
    }
  }
  INFO(equal << " of " << compared << " pixels away from edges agree (" << dark_side
             << " on dark sides)");
  CHECK(compared > 5000);
  CHECK(equal == compared);
  const std::vector<cgfs::Figure> figures = Figures({});
  CheckDrawn(figures, "stencil-shadows-stencil-writes", writes, kScale);
  CHECK(FindFigure(figures, "stencil-shadows").cost_view == "stencil-shadows-stencil-writes");
}
