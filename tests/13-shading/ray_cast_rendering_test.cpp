// RenderScene draws, with every shading model, what a ray through each pixel meets
// first, as an independent ray caster (tests/support) finds it: the depth test,
// clipping and culling of every shading path. Chapters 14 and 15 keep RenderScene and
// run this test too.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <vector>

#include "figure_checks.h"
#include "scenes.h"
#include "sphere_model.h"

using cgfs::test::Agreement;
using cgfs::test::CastCameraImage;
using cgfs::test::CastCameraOf;
using cgfs::test::CastSceneOf;
using cgfs::test::CompareInstances;
using cgfs::test::Describe;
using cgfs::test::InstanceColoredScene;

namespace {

// A floor 20 x 20 at y = -1.5, open (seen from both sides), facing up.
Model Floor() {
  Model floor;
  floor.vertices = {{-10, -1.5, 18}, {10, -1.5, 18}, {10, -1.5, -2}, {-10, -1.5, -2}};
  for (const std::array<int, 3>& v : {std::array{0, 1, 2}, std::array{0, 2, 3}}) {
    Triangle T;
    T.v = v;
    T.color = cgfs::kYellow;
    T.normals = {Vec3(0, 1, 0), Vec3(0, 1, 0), Vec3(0, 1, 0)};
    floor.triangles.push_back(T);
  }
  floor.closed = false;
  return floor;
}

// Figure 10-10's cubes, a sphere between them, a small cube in front of the sphere and
// a floor under everything: things hide one another; and a cube so close to a second
// camera that the near plane cuts it open.
Scene CubesAndSphere() {
  static const Model sphere = GenerateSphere(15, cgfs::kGreen);
  static const Model floor = Floor();
  Scene scene = SceneTransformedCubes();
  scene.instances.push_back({&sphere, {1.5, glm::dmat4(1.0), {1.75, -0.5, 7}}});
  scene.instances.push_back({&CubeModel(), {0.5, MakeOYRotationMatrix(20), {1.1, -0.4, 5.2}}});
  scene.instances.push_back({&floor, {}});
  return scene;
}

Scene CubeCutByTheNearPlane() {
  Scene scene;
  scene.instances = {{&CubeModel(), {1, MakeOYRotationMatrix(20), {0.3, 0.2, 1.6}}},
                     {&CubeModel(), {1, glm::dmat4(1.0), {-1, -0.5, 6}}}};
  return scene;
}

Agreement VisibilityOf(const Scene& scene, ShadingModel model) {
  std::vector<std::unique_ptr<Model>> models;
  const Scene colored = InstanceColoredScene(scene, models);
  Shading shading;
  shading.model = model;
  Canvas canvas(600, 600);
  RenderScene(colored, canvas, shading);
  const auto cast = CastCameraImage(CastSceneOf(scene), CastCameraOf(scene), 600, 600);
  return CompareInstances(cast, canvas, 2);
}

}  // namespace

TEST_CASE("every shading model shows what a ray through each pixel meets first",
          "[shading][ray-cast]") {
  for (const auto& [name, scene] :
       {std::pair{"cubes and sphere", CubesAndSphere()},
        std::pair{"a cube cut by the near plane", CubeCutByTheNearPlane()}}) {
    for (const ShadingModel model :
         {ShadingModel::kFlat, ShadingModel::kGouraud, ShadingModel::kPhong}) {
      const Agreement agreement = VisibilityOf(scene, model);
      INFO(name << ", shading model " << static_cast<int>(model) << ": " << Describe(agreement));
      CHECK(agreement.counted > 20000);
      CHECK(agreement.Fraction() >= 0.995);
    }
  }
}

namespace {

// The illumination equation ("Light", chapter 3) at world-space point P with unit
// normal N, seen from `eye`: written here again, apart from the chapters' code.
double Illumination(const Vec3& P, const Vec3& N, const Vec3& eye, double s,
                    const std::vector<Light>& lights) {
  double i = 0;
  const Vec3 V = eye - P;
  for (const Light& light : lights) {
    if (light.type == LightType::kAmbient) {
      i += light.intensity;
      continue;
    }
    const Vec3 L = light.type == LightType::kPoint ? light.position - P : light.direction;
    const double n_dot_l = glm::dot(N, L);
    if (n_dot_l > 0) {
      i += light.intensity * n_dot_l / glm::length(L);
    }
    const Vec3 R = 2.0 * N * n_dot_l - L;
    const double r_dot_v = glm::dot(R, V);
    if (r_dot_v > 0) {
      i += light.intensity * std::pow(r_dot_v / (glm::length(R) * glm::length(V)), s);
    }
  }
  return i;
}

// Chapter 14's three crates, untextured and white, as Figure 10-10's camera sees them:
// the one nearest the camera is cut by the right clipping plane.
Scene WhiteCrates() {
  static const Model white = [] {
    Model model = CubeModel();
    for (Triangle& T : model.triangles) {
      T.color = cgfs::kWhite;
    }
    return model;
  }();
  Scene scene;
  scene.camera = {{-3, 1, 2}, MakeOYRotationMatrix(-30)};
  scene.instances = {{&white, {0.75, glm::dmat4(1.0), {-1.5, 0, 7}}},
                     {&white, {1, MakeOYRotationMatrix(195), {1.25, 2.5, 7.5}}},
                     {&white, {1, MakeOYRotationMatrix(-30), {1.75, 0, 5}}}};
  scene.lights = {{LightType::kAmbient, 0.2},
                  {LightType::kDirectional, 0.2, {}, {-1, 0, 1}},
                  {LightType::kPoint, 0.6, {-3, 2, -10}}};
  return scene;
}

}  // namespace

TEST_CASE("Phong shading lights every pixel as the illumination equation does where a ray hits",
          "[shading][ray-cast]") {
  // White cubes with their faces' normals: a pixel is 255 x the light at the point it
  // shows, within a level or two (the point is the pixel's, the rasteriser's edges a
  // pixel off). Clipped faces too: the light depends on the point, not on the corners.
  const Scene scene = WhiteCrates();
  Canvas canvas(600, 600);
  RenderScene(scene, canvas);
  const auto cast = CastCameraImage(CastSceneOf(scene), CastCameraOf(scene), 600, 600);
  const auto faces = cgfs::test::LabelsOf(cast, cgfs::test::CubeFaceOf);
  Agreement agreement;
  for (int y = -300; y < 300; ++y) {
    for (int x = -300; x < 300; ++x) {
      const cgfs::test::CastHit& hit = cast.At(x, y);
      if (hit.instance < 0 || !faces.Inside(x, y, 2)) {
        continue;
      }
      const double expected =
          255 * Illumination(hit.point, hit.normal, scene.camera.position, 50, scene.lights);
      ++agreement.counted;
      agreement.agreeing += std::abs(canvas.GetPixel(x, y).r - std::min(expected, 255.0)) <= 2;
    }
  }
  INFO(Describe(agreement));
  CHECK(agreement.counted > 20000);
  CHECK(agreement.Fraction() >= 0.995);
}
