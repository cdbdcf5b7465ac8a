// RenderScene draws, with every shading model, what a ray through each pixel meets
// first, as an independent ray caster (tests/support) finds it: the depth test,
// clipping and culling of every shading path. Chapters 14 and 15 keep RenderScene and
// run this test too.
#include <catch2/catch.hpp>

#include <array>
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
