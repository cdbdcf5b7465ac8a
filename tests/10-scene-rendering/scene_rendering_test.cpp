// Models, instances, transforms and the camera (Listings 10-1 to 10-5), the
// matrices checked by what they do to vectors. Chapters 11 and 12 keep them and
// run these tests too.
#include <catch2/catch.hpp>

#include <cmath>

#include "cases.h"
#include "checks.h"
#include "scenes.h"

using Catch::Detail::Approx;
using cgfs::test::CheckNear;

namespace {

glm::dvec4 Point4(const Vec3& v) {
  return {v, 1.0};
}

// Where the full matrix chain of Listing 10-5 takes a model vertex, in camera space.
Vec3 CameraSpace(const Scene& scene, int instance, int vertex) {
  const Instance& I = scene.instances[static_cast<std::size_t>(instance)];
  const glm::dmat4 M = MakeCameraMatrix(scene.camera.position, scene.camera.orientation) *
                       MakeTransformMatrix(I.transform);
  return cgfs::ToCartesian(M * Point4(I.model->vertices[static_cast<std::size_t>(vertex)]));
}

}  // namespace

TEST_CASE("the cube model: 8 vertices, 12 triangles wound outwards", "[model]") {
  const Model& cube = CubeModel();
  REQUIRE(cube.vertices.size() == 8);
  REQUIRE(cube.triangles.size() == 12);
  for (const Triangle& T : cube.triangles) {
    const Vec3 V0 = cube.vertices[static_cast<std::size_t>(T.v[0])];
    const Vec3 V1 = cube.vertices[static_cast<std::size_t>(T.v[1])];
    const Vec3 V2 = cube.vertices[static_cast<std::size_t>(T.v[2])];
    const Vec3 normal = glm::cross(V1 - V0, V2 - V0);
    const Vec3 centre_of_triangle = (V0 + V1 + V2) / 3.0;  // the cube's centre is the origin
    CHECK(glm::dot(normal, centre_of_triangle) > 0);
  }
}

TEST_CASE("figure 10-2: the cube moved by T = (-1.5, 0, 7)", "[projection]") {
  const Canvas canvas(600, 600);
  const Vec3 T(-1.5, 0, 7);
  // Vertex 0 -> (-0.5, 1, 8) -> (-37.5, 75), truncated toward zero.
  CHECK(ProjectVertex(CubeModel().vertices[0] + T, canvas, Viewport{}) == Point{-37, 75});
  CHECK(ProjectVertex(CubeModel().vertices[6] + T, canvas, Viewport{}) == Point{-250, -100});
}

TEST_CASE("MakeTransformMatrix: the model matrix scales, then rotates, then translates",
          "[transform]") {
  // The example of "Model Transform": scale 1.5, 45 degrees about Y, then move by (1, 2, 3).
  const Transform transform{1.5, MakeOYRotationMatrix(45), {1, 2, 3}};
  CheckNear(cgfs::ToCartesian(MakeTransformMatrix(transform) * Point4({1, 0, 0})),
            {1 + 1.5 * std::sqrt(0.5), 2, 3 + 1.5 * std::sqrt(0.5)});
}

TEST_CASE("rotating then translating is not translating then rotating", "[transform]") {
  const glm::dmat4 R = MakeOYRotationMatrix(90);
  const glm::dmat4 T = MakeTranslationMatrix({0, 0, 5});
  CheckNear(cgfs::ToCartesian(T * R * Point4({0, 0, 1})), {-1, 0, 5});  // Figure 10-4
  CheckNear(cgfs::ToCartesian(R * T * Point4({0, 0, 1})), {-6, 0, 0});  // Figure 10-5
}

TEST_CASE("MakeCameraMatrix: the cases of 10-scene-rendering.json", "[transform]") {
  // The first is the camera of figure 10-10, worked out by hand:
  // [[0.866025, 0, -0.5, 3.598076], [0, 1, 0, -1], [0.5, 0, 0.866025, -0.232051], [0, 0, 0, 1]].
  for (const cgfs::test::FunctionCase& c :
       cgfs::test::CasesOf("10-scene-rendering.json", "MakeCameraMatrix")) {
    INFO(c.Describe());
    const glm::dmat4 M = MakeCameraMatrix(cgfs::test::ToVector(c.args.at("position")),
                                          cgfs::test::ToMatrix(c.args.at("orientation")));
    CHECK_THAT(cgfs::test::AsNumbers(M), cgfs::test::MatchesCase(c));
  }
}

TEST_CASE("MakeCameraMatrix: the camera's own position lands on the origin of camera space",
          "[transform]") {
  const glm::dmat4 M = MakeCameraMatrix({-3, 1, 2}, MakeOYRotationMatrix(-30));
  CheckNear(cgfs::ToCartesian(M * Point4({-3, 1, 2})), {0, 0, 0});
}

TEST_CASE("MovedCamera: along the camera's own axes, then turned left and up", "[transform]") {
  const Camera straight;  // at the origin, looking down +z
  const auto forward = [](const Camera& camera) {
    return Vec3(camera.orientation * glm::dvec4(0, 0, 1, 0));
  };
  // Turned 90 degrees to the left the camera looks down -x; 90 degrees up, down +y.
  CheckNear(forward(MovedCamera(straight, {{0, 0, 0}, 90, 0})), {-1, 0, 0});
  CheckNear(forward(MovedCamera(straight, {{0, 0, 0}, 0, 90})), {0, 1, 0});
  // Figure 10-10's camera at (-3, 1, 2), turned 30 degrees to the right, looks along
  // (sin 30, 0, cos 30); its right is (cos 30, 0, -sin 30) and its up +y.
  const Camera turned = SceneTransformedCubes().camera;
  CheckNear(MovedCamera(turned, {{0, 0, 1}, 0, 0}).position, {-2.5, 1, 2.866025});
  CheckNear(MovedCamera(turned, {{1, 0, 0}, 0, 0}).position, {-2.133975, 1, 1.5});
  CheckNear(MovedCamera(turned, {{0, 1, 0}, 0, 0}).position, {-3, 2, 2});
  // Turning 30 degrees to the left undoes the figure's turn: it looks down +z again.
  CheckNear(forward(MovedCamera(turned, {{0, 0, 0}, 30, 0})), {0, 0, 1});
  // No view, the camera itself.
  const Camera same = MovedCamera(turned, {});
  CHECK(same.position == turned.position);
  CHECK(same.orientation == turned.orientation);
}

TEST_CASE("instance A of figure 10-10: composite matrix and vertices", "[transform]") {
  const Scene scene = SceneTransformedCubes();
  const glm::dmat4 M = MakeCameraMatrix(scene.camera.position, scene.camera.orientation) *
                       MakeTransformMatrix(scene.instances[0].transform);
  CheckNear(Vec3(M * glm::dvec4(1, 0, 0, 0)), {0.649519, 0, 0.375});
  CheckNear(Vec3(M * glm::dvec4(0, 1, 0, 0)), {0, 0.75, 0});
  CheckNear(Vec3(M * glm::dvec4(0, 0, 1, 0)), {-0.375, 0, 0.649519});
  CheckNear(Vec3(M * glm::dvec4(0, 0, 0, 1)), {-1.200962, -1, 5.080127});  // its centre

  const Canvas canvas(600, 600);
  // x = 0.866025 * 2.25 - 0.5 * 5.75 = -0.926443 (worked out by hand twice; a
  // rounding slip gives -0.926422).
  CheckNear(CameraSpace(scene, 0, 0), {-0.926443, -0.25, 6.104646});
  CHECK(ProjectVertex(CameraSpace(scene, 0, 0), canvas, Viewport{}) == Point{-91, -24});
  CheckNear(CameraSpace(scene, 0, 6), {-1.475481, -1.75, 4.055608});
  CHECK(ProjectVertex(CameraSpace(scene, 0, 6), canvas, Viewport{}) == Point{-218, -258});
}

TEST_CASE("instance B of figure 10-10: vertices", "[transform]") {
  const Scene scene = SceneTransformedCubes();
  const Canvas canvas(600, 600);
  CheckNear(CameraSpace(scene, 1, 0), {0.930608, 2.5, 5.473931});
  CHECK(ProjectVertex(CameraSpace(scene, 1, 0), canvas, Viewport{}) == Point{102, 274});
  CheckNear(CameraSpace(scene, 1, 4), {-0.483606, 2.5, 6.888145});
  CHECK(ProjectVertex(CameraSpace(scene, 1, 4), canvas, Viewport{}) == Point{-42, 217});
  // Its centre, the model's origin.
  const glm::dmat4 M = MakeCameraMatrix(scene.camera.position, scene.camera.orientation) *
                       MakeTransformMatrix(scene.instances[1].transform);
  CheckNear(Vec3(M * glm::dvec4(0, 0, 0, 1)), {0.930608, 1.5, 6.888145});
}

TEST_CASE("ApplyTransform: the cases of 10-scene-rendering.json", "[transform]") {
  for (const cgfs::test::FunctionCase& c :
       cgfs::test::CasesOf("10-scene-rendering.json", "ApplyTransform")) {
    INFO(c.Describe());
    const nlohmann::json& transform = c.args.at("transform");
    const Vec3 moved = ApplyTransform(cgfs::test::ToVector(c.args.at("vertex")),
                                      Transform{cgfs::test::ToNumber(transform.at("scale")),
                                                cgfs::test::ToMatrix(transform.at("rotation")),
                                                cgfs::test::ToVector(transform.at("translation"))});
    CHECK_THAT(cgfs::test::AsNumbers(moved), cgfs::test::MatchesCase(c));
  }
}

TEST_CASE("ApplyTransform scales, then rotates, then translates", "[transform]") {
  // The example of "Model Transform": scale 1.5, 45 degrees about Y, then move by (1, 2, 3).
  const Transform transform{1.5, MakeOYRotationMatrix(45), {1, 2, 3}};
  const Vec3 moved = ApplyTransform({1, 0, 0}, transform);
  // (1,0,0) -> (1.5,0,0) -> OY(45): (1.5 cos 45, 0, 1.5 sin 45) -> + (1, 2, 3)
  CheckNear(moved, {1 + 1.5 * std::sqrt(0.5), 2, 3 + 1.5 * std::sqrt(0.5)});
  // The matrix of "The Transform Matrix" does the same to every vertex.
  for (const Vec3& V : CubeModel().vertices) {
    CheckNear(cgfs::ToCartesian(MakeTransformMatrix(transform) * glm::dvec4(V, 1.0)),
              ApplyTransform(V, transform));
  }
}
