// Spec §3.4 and §4.5: the equations of chapters 2 and 3 with hand-checked values.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "printing.h"
#include "raytracer.h"

using Catch::Detail::Approx;

namespace {

const Sphere kRedSphere{{0, -1, 3}, 1, cgfs::kRed};

}  // namespace

TEST_CASE("CanvasToViewport scales pixels to the 1x1 viewport at d = 1", "[equations]") {
  const Canvas canvas(600, 600);
  const Viewport viewport;  // Vw = Vh = d = 1
  CHECK(CanvasToViewport(300, -150, canvas, viewport) == Vec3(0.5, -0.25, 1));
  CHECK(CanvasToViewport(0, 0, canvas, viewport) == Vec3(0, 0, 1));
}

TEST_CASE("the 1x1 viewport at d = 1 gives a 53.13 degree field of view", "[equations]") {
  const Viewport viewport;
  const double fov = 2 * std::atan(viewport.width / 2 / viewport.distance);
  CHECK(fov * 180 / std::numbers::pi == Approx(53.13).margin(0.005));
}

TEST_CASE("IntersectRaySphere: a ray through the centre hits at both sides", "[equations]") {
  const auto [t1, t2] = IntersectRaySphere({0, 0, 0}, {0, 0, 1}, {{0, 0, 5}, 1, cgfs::kRed});
  CHECK(t1 == 6);
  CHECK(t2 == 4);
}

TEST_CASE("IntersectRaySphere: a = 10, b = -20, c = 9 against the red sphere", "[equations]") {
  const auto [t1, t2] = IntersectRaySphere({0, 0, 0}, {0, -1, 3}, kRedSphere);
  CHECK(t1 == Approx(1.3162278));
  CHECK(t2 == Approx(0.6837722));
  CHECK(t1 >= t2);
}

TEST_CASE("IntersectRaySphere: a miss returns (inf, inf)", "[equations]") {
  const auto [t1, t2] = IntersectRaySphere({0, 0, 0}, {0, 0, 1}, {{0, 2, 5}, 1, cgfs::kRed});
  CHECK(t1 == cgfs::kInf);
  CHECK(t2 == cgfs::kInf);
}

TEST_CASE("IntersectRaySphere: the central ray grazes the top of the red sphere", "[equations]") {
  // disc = 0 exactly: a tangent counts as a hit with t1 = t2 = 3 at (0, 0, 3).
  const auto [t1, t2] = IntersectRaySphere({0, 0, 0}, {0, 0, 1}, kRedSphere);
  CHECK(t1 == 3);
  CHECK(t2 == 3);
}

TEST_CASE("TraceRay keeps the nearest root inside [t_min, t_max]", "[equations]") {
  Scene scene;
  scene.background_color = cgfs::kWhite;
  scene.spheres = {{{0, 0, 5}, 1, cgfs::kRed}, {{0, 0, 10}, 1, cgfs::kBlue}};
  scene.lights = {{LightType::kAmbient, 1.0, {}, {}}};  // full ambient light: flat colours
  CHECK(TraceRay({0, 0, 0}, {0, 0, 1}, 1, cgfs::kInf, scene) == cgfs::kRed);
  // The red sphere spans t in [4, 6]: start past it and the blue one is nearest.
  CHECK(TraceRay({0, 0, 0}, {0, 0, 1}, 6.5, cgfs::kInf, scene) == cgfs::kBlue);
  // Inside the red sphere, its far side (t = 6) is the nearest root past t_min.
  CHECK(TraceRay({0, 0, 0}, {0, 0, 1}, 5, cgfs::kInf, scene) == cgfs::kRed);
  // Closed interval: a root exactly at t_max still counts.
  CHECK(TraceRay({0, 0, 0}, {0, 0, 1}, 1, 4, scene) == cgfs::kRed);
  CHECK(TraceRay({0, 0, 0}, {0, 0, 1}, 1, 3.99, scene) == cgfs::kWhite);
  // Nothing behind the projection plane: t_min = 1 skips a sphere at t < 1.
  scene.spheres = {{{0, 0, 0.5}, 0.1, cgfs::kRed}};
  CHECK(TraceRay({0, 0, 0}, {0, 0, 1}, 1, cgfs::kInf, scene) == cgfs::kWhite);
}

namespace {

Scene SceneWithLights(std::vector<Light> lights) {
  Scene scene;
  scene.lights = std::move(lights);
  return scene;
}

}  // namespace

TEST_CASE("ComputeLighting: diffuse plus specular from one point light", "[equations]") {
  // Diffuse 0.6 * cos 45° = 0.424264; R = (-1, 1, 0), cos(R, V) = 1/sqrt 2, (1/sqrt 2)^10 = 1/32.
  const Scene scene = SceneWithLights({{LightType::kPoint, 0.6, {1, 1, 0}, {}}});
  CHECK(ComputeLighting({0, 0, 0}, {0, 1, 0}, {0, 1, 0}, 10, scene) ==
        Approx(0.424264 + 0.01875).epsilon(1e-6));
  CHECK(ComputeLighting({0, 0, 0}, {0, 1, 0}, {0, 1, 0}, 10, scene) == Approx(0.443014));
}

TEST_CASE("ComputeLighting: ambient plus directional, whatever the direction's length",
          "[equations]") {
  const Scene scene = SceneWithLights(
      {{LightType::kAmbient, 0.2, {}, {}}, {LightType::kDirectional, 0.8, {}, {0, 2, 0}}});
  CHECK(ComputeLighting({0, 0, 0}, {0, 1, 0}, {0, 1, 0}, -1, scene) == Approx(1.0));
}

TEST_CASE("ComputeLighting: the chapter's lights on top of the red sphere, diffuse only",
          "[equations]") {
  // 0.2 + 0.6 * 1/sqrt(14) + 0.2 * 4/sqrt(33)
  CHECK(ComputeLighting({0, 0, 3}, {0, 1, 0}, {0, 0, -1}, -1, SceneDiffuse()) == Approx(0.499619));
}

TEST_CASE("ComputeLighting: light from behind the surface adds no diffuse light", "[equations]") {
  const Scene scene = SceneWithLights(
      {{LightType::kPoint, 0.6, {0, -5, 0}, {}}, {LightType::kDirectional, 0.4, {}, {0, -1, 0}}});
  CHECK(ComputeLighting({0, 0, 0}, {0, 1, 0}, {0, 1, 0}, -1, scene) == 0);
}

TEST_CASE("ComputeLighting: the specular term is not guarded by n_dot_l > 0 (book behaviour)",
          "[equations]") {
  // L = (1, -0.1, 0) comes from just below the surface, so no diffuse light; its
  // mirror image R = (-1, -0.1, 0) points straight at V, so cos = 1 and the
  // specular term adds the whole intensity.
  const Scene scene = SceneWithLights({{LightType::kPoint, 0.6, {1, -0.1, 0}, {}}});
  CHECK(ComputeLighting({0, 0, 0}, {0, 1, 0}, {-1, -0.1, 0}, 10, scene) == Approx(0.6));
  CHECK(ComputeLighting({0, 0, 0}, {0, 1, 0}, {-1, -0.1, 0}, -1, scene) == 0);
}

TEST_CASE("TraceRay lights the hit point with the sphere's unit normal", "[equations]") {
  // A directional light towards the camera; the central ray hits the sphere at
  // (0, 0, 4) where N = (0, 0, -1): full intensity. A radius of 2 checks that N
  // is normalised (an unnormalised N would double the diffuse term).
  Scene scene = SceneWithLights({{LightType::kDirectional, 0.5, {}, {0, 0, -1}}});
  scene.spheres = {{{0, 0, 6}, 2, {200, 100, 50}}};
  CHECK(TraceRay({0, 0, 0}, {0, 0, 1}, 1, cgfs::kInf, scene) == Color(100, 50, 25));
  // Seen from above at (0, 2, 6) the normal is (0, 1, 0): perpendicular to the light.
  CHECK(TraceRay({0, 10, 6}, {0, -1, 0}, 1, cgfs::kInf, scene) == Color(0, 0, 0));
}

TEST_CASE("RenderScene paints every pixel of the canvas exactly once", "[equations]") {
  Scene empty;
  empty.background_color = cgfs::kBlack;
  Canvas canvas(40, 30, cgfs::kWhite);
  RenderScene(empty, canvas);
  CHECK(canvas.GetImage() == cgfs::Image(40, 30, cgfs::Rgb8{0, 0, 0}));
}
