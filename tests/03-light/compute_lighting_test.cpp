// ComputeLighting with hand-checked values. The scenes have no spheres,
// so chapter 4's shadow rays find nothing and it runs these tests unchanged.
#include <catch2/catch.hpp>

#include <utility>
#include <vector>

#include "printing.h"
#include "raytracer.h"

using Catch::Detail::Approx;

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
  const Scene scene = SceneWithLights({{LightType::kAmbient, 0.2, {}, {}},
                                       {LightType::kPoint, 0.6, {2, 1, 0}, {}},
                                       {LightType::kDirectional, 0.2, {}, {1, 4, 4}}});
  CHECK(ComputeLighting({0, 0, 3}, {0, 1, 0}, {0, 0, -1}, -1, scene) == Approx(0.499619));
}

TEST_CASE("ComputeLighting: light from behind the surface adds no diffuse light", "[equations]") {
  const Scene scene = SceneWithLights(
      {{LightType::kPoint, 0.6, {0, -5, 0}, {}}, {LightType::kDirectional, 0.4, {}, {0, -1, 0}}});
  CHECK(ComputeLighting({0, 0, 0}, {0, 1, 0}, {0, 1, 0}, -1, scene) == 0);
}

TEST_CASE("ComputeLighting: light from just below the surface adds no diffuse light",
          "[equations]") {
  // L = (1, -0.1, 0): n_dot_l < 0. Matte (s = -1), so only the diffuse guard matters.
  const Scene scene = SceneWithLights({{LightType::kPoint, 0.6, {1, -0.1, 0}, {}}});
  CHECK(ComputeLighting({0, 0, 0}, {0, 1, 0}, {-1, -0.1, 0}, -1, scene) == 0);
}

TEST_CASE("ComputeLighting: the specular term is not guarded by n_dot_l > 0 (book behaviour)",
          "[equations]") {
  // The same light, shiny (s = 10): its mirror image R = (-1, -0.1, 0) points straight
  // at V, so cos = 1 and the specular term adds the whole intensity, although the
  // light is below the surface. (The previous test pins the diffuse part at 0.)
  const Scene scene = SceneWithLights({{LightType::kPoint, 0.6, {1, -0.1, 0}, {}}});
  CHECK(ComputeLighting({0, 0, 0}, {0, 1, 0}, {-1, -0.1, 0}, 10, scene) == Approx(0.6));
}
