// ClosestIntersection, shadows, ReflectRay and the recursive TraceRay.
#include <catch2/catch.hpp>

#include <utility>
#include <vector>

#include "printing.h"
#include "scenes.h"

using Catch::Detail::Approx;
using cgfs::test::IsSameImageAs;

namespace {

Scene SceneLitBy(std::vector<Light> lights) {
  Scene scene;
  scene.lights = std::move(lights);
  return scene;
}

}  // namespace

TEST_CASE("TraceRay keeps the nearest root inside [t_min, t_max]", "[equations]") {
  Scene scene;
  scene.background_color = cgfs::kWhite;
  scene.spheres = {{{0, 0, 5}, 1, cgfs::kRed}, {{0, 0, 10}, 1, cgfs::kBlue}};
  scene.lights = {{LightType::kAmbient, 1.0, {}, {}}};  // full ambient light: flat colours
  CHECK(TraceRay({0, 0, 0}, {0, 0, 1}, 1, cgfs::kInf, 0, scene) == cgfs::kRed);
  // The red sphere spans t in [4, 6]: start past it and the blue one is nearest.
  CHECK(TraceRay({0, 0, 0}, {0, 0, 1}, 6.5, cgfs::kInf, 0, scene) == cgfs::kBlue);
  // Inside the red sphere, its far side (t = 6) is the nearest root past t_min.
  CHECK(TraceRay({0, 0, 0}, {0, 0, 1}, 5, cgfs::kInf, 0, scene) == cgfs::kRed);
  // Closed interval: a root exactly at t_max still counts.
  CHECK(TraceRay({0, 0, 0}, {0, 0, 1}, 1, 4, 0, scene) == cgfs::kRed);
  CHECK(TraceRay({0, 0, 0}, {0, 0, 1}, 1, 3.99, 0, scene) == cgfs::kWhite);
  // Nothing behind the projection plane: t_min = 1 skips a sphere at t < 1.
  scene.spheres = {{{0, 0, 0.5}, 0.1, cgfs::kRed}};
  CHECK(TraceRay({0, 0, 0}, {0, 0, 1}, 1, cgfs::kInf, 0, scene) == cgfs::kWhite);
}

TEST_CASE("TraceRay lights the hit point with the sphere's unit normal", "[equations]") {
  // A directional light towards the camera; the central ray hits the sphere at
  // (0, 0, 4) where N = (0, 0, -1): full intensity. A radius of 2 checks that N
  // is normalised (an unnormalised N would double the diffuse term).
  Scene scene = SceneLitBy({{LightType::kDirectional, 0.5, {}, {0, 0, -1}}});
  scene.spheres = {{{0, 0, 6}, 2, {200, 100, 50}}};
  CHECK(TraceRay({0, 0, 0}, {0, 0, 1}, 1, cgfs::kInf, 0, scene) == Color(100, 50, 25));
  // Seen from above at (0, 2, 6) the normal is (0, 1, 0): perpendicular to the light.
  CHECK(TraceRay({0, 10, 6}, {0, -1, 0}, 1, cgfs::kInf, 0, scene) == Color(0, 0, 0));
}

TEST_CASE("RenderScene paints every pixel of the canvas exactly once", "[equations]") {
  Scene empty;
  empty.background_color = cgfs::kBlack;
  Canvas canvas(40, 30, cgfs::kWhite);
  RenderScene(empty, kDefaultRecursionDepth, canvas);
  CHECK_THAT(canvas.GetImage(), IsSameImageAs(cgfs::Image(40, 30, cgfs::Rgb8{0, 0, 0})));
}

TEST_CASE("ClosestIntersection returns the nearest sphere and its t", "[equations]") {
  Scene scene;
  scene.spheres = {{{0, 0, 10}, 1, cgfs::kBlue}, {{0, 0, 5}, 1, cgfs::kRed}};
  const auto [sphere, t] = ClosestIntersection({0, 0, 0}, {0, 0, 1}, 1, cgfs::kInf, scene);
  REQUIRE(sphere == &scene.spheres[1]);
  CHECK(t == 4);
  const auto [none, t_none] = ClosestIntersection({0, 0, 0}, {0, 1, 0}, 1, cgfs::kInf, scene);
  CHECK(none == nullptr);
  CHECK(t_none == cgfs::kInf);
}

TEST_CASE("ReflectRay mirrors a vector about a unit normal", "[equations]") {
  CHECK(ReflectRay({1, 2, 3}, {0, 1, 0}) == Vec3(-1, 2, -3));
  // R need not be unit length; its mirror image keeps the length.
  const Vec3 mirrored = ReflectRay({3, -4, 0}, {0, 1, 0});
  CHECK(mirrored == Vec3(-3, -4, 0));
  CHECK(glm::length(mirrored) == 5);
}

TEST_CASE("ComputeLighting: a point light's shadow ray stops at the light (t_max = 1)",
          "[equations]") {
  // The light is at (0, 2, 0), so L = (0, 2, 0) from P = (0, 0, 0): t = 1 at the light.
  Scene scene = SceneLitBy({{LightType::kPoint, 1.0, {0, 2, 0}, {}}});
  scene.spheres = {{{0, 5, 0}, 1, cgfs::kRed}};  // beyond the light: t = 2 .. 3
  CHECK(ComputeLighting({0, 0, 0}, {0, 1, 0}, {0, 1, 0}, -1, scene) == 1.0);
  scene.spheres = {{{0, 1, 0}, 0.5, cgfs::kRed}};  // between P and the light: t = 0.25 .. 0.75
  CHECK(ComputeLighting({0, 0, 0}, {0, 1, 0}, {0, 1, 0}, -1, scene) == 0.0);
}

TEST_CASE("ComputeLighting: a directional light's shadow ray has no end (t_max = inf)",
          "[equations]") {
  Scene scene = SceneLitBy({{LightType::kDirectional, 1.0, {}, {0, 1, 0}}});
  scene.spheres = {{{0, 1000, 0}, 1, cgfs::kRed}};
  CHECK(ComputeLighting({0, 0, 0}, {0, 1, 0}, {0, 1, 0}, -1, scene) == 0.0);
  scene.spheres = {{{0, -1000, 0}, 1, cgfs::kRed}};  // behind P: t < 0
  CHECK(ComputeLighting({0, 0, 0}, {0, 1, 0}, {0, 1, 0}, -1, scene) == 1.0);
}

TEST_CASE("ComputeLighting: shadow rays start at epsilon, so a point does not shadow itself",
          "[equations]") {
  // P lies on the sphere (up to rounding): its shadow ray finds the sphere at t ~ 0.
  Scene scene = SceneLitBy({{LightType::kDirectional, 1.0, {}, {0, 1, 0}}});
  scene.spheres = {{{0, -1, 0}, 1, cgfs::kRed}};
  CHECK(ComputeLighting({0, 0, 0}, {0, 1, 0}, {0, 1, 0}, -1, scene) == 1.0);
  scene.epsilon = 0;
  CHECK(ComputeLighting({0, 0, 0}, {0, 1, 0}, {0, 1, 0}, -1, scene) == 0.0);
}

TEST_CASE("TraceRay: recursion depth 0 returns the local colour", "[equations]") {
  const Scene scene = SceneReflections();
  const Canvas canvas(600, 600);
  const Vec3 D = CanvasToViewport(0, -150, canvas, scene.viewport);
  const auto [sphere, t] = ClosestIntersection({0, 0, 0}, D, 1, cgfs::kInf, scene);
  REQUIRE(sphere != nullptr);
  REQUIRE(sphere->reflective > 0);
  const Vec3 P = t * D;
  const Vec3 N = glm::normalize(P - sphere->center);
  const Color local = sphere->color * ComputeLighting(P, N, -D, sphere->specular, scene);
  CHECK(TraceRay({0, 0, 0}, D, 1, cgfs::kInf, 0, scene) == local);
  CHECK(TraceRay({0, 0, 0}, D, 1, cgfs::kInf, 3, scene) != local);
}

TEST_CASE("TraceRay: the reflection blend is local * (1 - r) + reflected * r", "[equations]") {
  // A black half-mirror straight ahead; its reflection looks back past the camera
  // at the white background: 0 * 0.5 + 255 * 0.5.
  Scene scene = SceneLitBy({{LightType::kAmbient, 1.0, {}, {}}});
  scene.background_color = cgfs::kWhite;
  scene.spheres = {{{0, 0, 5}, 1, cgfs::kBlack, -1, 0.5}};
  CHECK(TraceRay({0, 0, 0}, {0, 0, 1}, 1, cgfs::kInf, 1, scene) == Color(127.5, 127.5, 127.5));
  // A surface that is not reflective stops the recursion whatever the depth.
  scene.spheres[0].reflective = 0;
  CHECK(TraceRay({0, 0, 0}, {0, 0, 1}, 1, cgfs::kInf, 5, scene) == Color(0, 0, 0));
}

TEST_CASE("TraceRay: two mirrors facing each other stop at the recursion limit", "[equations]") {
  Scene scene = SceneLitBy({{LightType::kAmbient, 1.0, {}, {}}});
  scene.spheres = {{{0, 0, 5}, 1, cgfs::kRed, -1, 1.0}, {{0, 0, -5}, 1, cgfs::kBlue, -1, 1.0}};
  // The bounces alternate between the two; with r = 1 only the last sphere's own
  // colour remains: red after an even number of bounces, blue after an odd one.
  CHECK(TraceRay({0, 0, 0}, {0, 0, 1}, 1, cgfs::kInf, 0, scene) == cgfs::kRed);
  CHECK(TraceRay({0, 0, 0}, {0, 0, 1}, 1, cgfs::kInf, 1, scene) == cgfs::kBlue);
  CHECK(TraceRay({0, 0, 0}, {0, 0, 1}, 1, cgfs::kInf, 10, scene) == cgfs::kRed);
  CHECK(TraceRay({0, 0, 0}, {0, 0, 1}, 1, cgfs::kInf, 11, scene) == cgfs::kBlue);
}
