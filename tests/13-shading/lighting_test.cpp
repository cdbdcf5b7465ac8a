// Chapter 3's illumination equation in the rasterizer, and the lights brought into
// camera space.
#include <catch2/catch.hpp>

#include <cmath>

#include "checks.h"
#include "scenes.h"

using Catch::Detail::Approx;
using cgfs::test::CheckNear;

TEST_CASE("ComputeLighting: chapter 3's values", "[lighting]") {
  const std::vector<Light> point = {{LightType::kPoint, 0.6, {1, 1, 0}}};
  // P = 0, N = V = (0, 1, 0), s = 10: diffuse 0.6/sqrt(2), specular 0.6 (1/sqrt(2))^10.
  CHECK(ComputeLighting({0, 0, 0}, {0, 1, 0}, {0, 1, 0}, 10, point) == Approx(0.443014));
  CHECK(ComputeLighting({0, 0, 0}, {0, 1, 0}, {0, 1, 0}, 10, point, {true, false}) ==
        Approx(0.424264));
  CHECK(ComputeLighting({0, 0, 0}, {0, 1, 0}, {0, 1, 0}, 10, point, {false, true}) ==
        Approx(0.01875));
  // Ambient 0.2 and a directional light 0.8 along (0, 2, 0): its length does not matter.
  const std::vector<Light> ambient_directional = {{LightType::kAmbient, 0.2},
                                                  {LightType::kDirectional, 0.8, {}, {0, 2, 0}}};
  CHECK(ComputeLighting({0, 0, 0}, {0, 1, 0}, {0, 1, 0}, -1, ambient_directional) == Approx(1.0));
  // The book's three lights at the top of the red sphere, diffuse only.
  const std::vector<Light> book = {{LightType::kAmbient, 0.2},
                                   {LightType::kPoint, 0.6, {2, 1, 0}},
                                   {LightType::kDirectional, 0.2, {}, {1, 4, 4}}};
  CHECK(ComputeLighting({0, 0, 3}, {0, 1, 0}, {0, 0, -3}, -1, book) == Approx(0.499619));
}

TEST_CASE("ComputeLighting: the view vector goes from the point to the camera", "[lighting]") {
  // A surface at z = 5 facing the camera, lit from the camera: the mirror direction
  // of the light points back at the camera, so V = -P (camera space) sees the full
  // highlight. The book's V = P - C points away from the camera and sees none.
  const std::vector<Light> at_camera = {{LightType::kPoint, 0.6, {0, 0, 0}}};
  const Vec3 P(0, 0, 5);
  const Vec3 N(0, 0, -1);
  CHECK(ComputeLighting(P, N, -P, 50, at_camera, {false, true}) == Approx(0.6));
  CHECK(ComputeLighting(P, N, P, 50, at_camera, {false, true}) == 0);
}

TEST_CASE("TransformLights: positions move and turn, directions only turn", "[lighting]") {
  const std::vector<Light> lights = {{LightType::kAmbient, 0.2},
                                     {LightType::kPoint, 0.6, {1, 2, 3}},
                                     {LightType::kDirectional, 0.2, {}, {0, 0, 1}}};
  // A camera at (1, 1, 1), not turned: only positions change.
  const std::vector<Light> moved =
      TransformLights(lights, MakeCameraMatrix({1, 1, 1}, glm::dmat4(1)));
  CheckNear(moved[1].position, {0, 1, 2});
  CheckNear(moved[2].direction, {0, 0, 1});
  CHECK(moved[0].intensity == 0.2);
  // A camera turned by OY(90), which turns +X into +Z: in camera space, what was +Z
  // (where the camera's right is now) is +X.
  const std::vector<Light> turned =
      TransformLights(lights, MakeCameraMatrix({0, 0, 0}, MakeOYRotationMatrix(90)));
  CheckNear(turned[2].direction, {1, 0, 0});
  CheckNear(turned[1].position, {3, 2, -1});
}
