// Listings 10-1 to 10-4, and what happens to geometry the camera cannot project.
#include <catch2/catch.hpp>

#include <cmath>

#include "checks.h"
#include "rasterizer.h"

using cgfs::test::CheckNear;

TEST_CASE("ApplyTransform scales, then rotates, then translates", "[transform]") {
  // The example of "Model Transform": scale 1.5, 45 degrees about Y, then move by (1, 2, 3).
  const Transform transform{1.5, cgfs::MakeOYRotationMatrix(45), {1, 2, 3}};
  const Vec3 moved = ApplyTransform({1, 0, 0}, transform);
  // (1,0,0) -> (1.5,0,0) -> OY(45): (1.5 cos 45, 0, 1.5 sin 45) -> + (1, 2, 3)
  CheckNear(moved, {1 + 1.5 * std::sqrt(0.5), 2, 3 + 1.5 * std::sqrt(0.5)});
  // The matrix of "The Transform Matrix" does the same to every vertex.
  for (const Vec3& V : CubeModel().vertices) {
    CheckNear(cgfs::ToCartesian(MakeTransformMatrix(transform) * glm::dvec4(V, 1.0)),
              ApplyTransform(V, transform));
  }
}

TEST_CASE("RenderInstance and RenderScene agree when the camera is at the origin", "[render]") {
  // Listing 10-3 (ApplyTransform per vertex) and Listing 10-5 (one matrix per instance).
  const Scene scene = SceneTwoCubes();
  Canvas by_instance(600, 600);
  for (const Instance& I : scene.instances) {
    RenderInstance(I, by_instance, scene.viewport);
  }
  Canvas by_matrix(600, 600);
  RenderScene(scene, by_matrix);
  CHECK(by_instance.GetImage() == by_matrix.GetImage());
}

TEST_CASE("an instance behind the camera is skipped, not drawn upside down", "[render]") {
  // The third cube of chapter 11's scene lies behind this camera.
  Scene scene = SceneTransformedCubes();
  Canvas without(600, 600);
  RenderScene(scene, without);
  scene.instances.push_back({&CubeModel(), {1, cgfs::MakeOYRotationMatrix(195), {0, 0, -10}}});
  Canvas with(600, 600);
  RenderScene(scene, with);
  CHECK(with.GetImage() == without.GetImage());
}

TEST_CASE("the untransformed cube around the camera draws only what it can project", "[render]") {
  // Its vertices have z = +1 (on the projection plane, at x, y = +-600 pixels) or
  // z = -1 (behind the camera): only the two triangles of the face z = +1 are drawn,
  // and of them only the diagonal crosses the canvas.
  Canvas canvas(600, 600);
  RenderObject(CubeModel().vertices, CubeModel().triangles, canvas, Viewport{});
  Canvas front_face(600, 600);
  DrawWireframeTriangle({600, 600}, {-600, 600}, {-600, -600}, cgfs::kRed, front_face);
  DrawWireframeTriangle({600, 600}, {-600, -600}, {600, -600}, cgfs::kRed, front_face);
  CHECK(canvas.GetImage() == front_face.GetImage());
}
