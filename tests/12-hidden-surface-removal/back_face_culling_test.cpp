// "Back Face Culling" and "Classifying Triangles" (Listing 12-1).
#include <catch2/catch.hpp>

#include <algorithm>
#include <vector>

#include "back_face_culling.h"
#include "cases.h"
#include "scenes.h"

namespace {

const Vec3 kCamera(0, 0, 0);

// The scene's instances in camera space, clipped: what RenderScene culls.
CameraSpaceScene ClippedCameraSpaceScene(const Scene& scene) {
  const glm::dmat4 M_camera = MakeCameraMatrix(scene.camera.position, scene.camera.orientation);
  CameraSpaceScene camera_space_scene;
  for (const Instance& I : scene.instances) {
    camera_space_scene.instances.push_back(
        TransformToCameraSpace(I, M_camera * MakeTransformMatrix(I.transform)));
  }
  return ClipScene(camera_space_scene, ClippingPlanes(scene.viewport.distance));
}

// {"vertices": [[x, y, z], ...], "triangles": [{"v": [i, j, k], "color": [r, g, b]}, ...]}.
Model ModelOfCullingCase(const nlohmann::json& object) {
  Model model;
  for (const nlohmann::json& vertex : object.at("vertices")) {
    model.vertices.push_back(cgfs::test::ToVector(vertex));
  }
  for (const nlohmann::json& triangle : object.at("triangles")) {
    Triangle T;
    T.v = triangle.at("v").get<std::array<int, 3>>();
    T.color = cgfs::test::ToColor(triangle.at("color"));
    model.triangles.push_back(T);
  }
  return model;
}

std::vector<Color> ColorsOf(const Model& model) {
  std::vector<Color> colors;
  for (const Triangle& T : model.triangles) {
    colors.push_back(T.color);
  }
  return colors;
}

}  // namespace

TEST_CASE("IsBackFacing: the cases of 12-hidden-surface-removal.json", "[culling]") {
  using cgfs::test::ToVector;
  for (const cgfs::test::FunctionCase& c :
       cgfs::test::CasesOf("12-hidden-surface-removal.json", "IsBackFacing")) {
    INFO(c.Describe());
    const bool back = IsBackFacing(ToVector(c.args.at("A")), ToVector(c.args.at("B")),
                                   ToVector(c.args.at("C")), ToVector(c.args.at("camera")));
    CHECK_THAT(cgfs::test::AsNumbers(back ? 1.0 : 0.0), cgfs::test::MatchesCase(c));
  }
}

TEST_CASE("CullBackFaces: the cases of 12-hidden-surface-removal.json", "[culling]") {
  for (const cgfs::test::FunctionCase& c :
       cgfs::test::CasesOf("12-hidden-surface-removal.json", "CullBackFaces")) {
    INFO(c.Describe());
    Model object = ModelOfCullingCase(c.args.at("object"));
    CullBackFaces(object, cgfs::test::ToVector(c.args.at("camera")));
    std::vector<double> kept;  // each triangle's vertex indices, in order
    for (const Triangle& T : object.triangles) {
      kept.insert(kept.end(), T.v.begin(), T.v.end());
    }
    CHECK_THAT(kept, cgfs::test::MatchesCase(c));
  }
}

TEST_CASE("IsBackFacing: counter-clockwise on the canvas is back-facing", "[culling]") {
  const Vec3 A(0, 0, 5), B(1, 0, 5), C(0, 1, 5);
  // N = (B - A) x (C - A) = (0, 0, 1), V = -A = (0, 0, -5): <N, V> = -5.
  CHECK(IsBackFacing(A, B, C, kCamera));
  // A, C, B: N = (0, 0, -1), <N, V> = 5, clockwise as the camera sees it.
  CHECK_FALSE(IsBackFacing(A, C, B, kCamera));
  // Any rotation of the order is the same triangle, facing the same way.
  CHECK(IsBackFacing(B, C, A, kCamera));
  CHECK_FALSE(IsBackFacing(C, B, A, kCamera));
}

TEST_CASE("IsBackFacing: edge-on and degenerate triangles count as back-facing", "[culling]") {
  // In the plane y = 0, which holds the camera: <N, V> = 0.
  CHECK(IsBackFacing({0, 0, 5}, {1, 0, 5}, {0, 0, 6}, kCamera));
  CHECK(IsBackFacing({0, 0, 5}, {0, 0, 6}, {1, 0, 5}, kCamera));
  // Three points on a line: N = 0.
  CHECK(IsBackFacing({0, 0, 5}, {1, 1, 5}, {2, 2, 5}, kCamera));
}

TEST_CASE("IsBackFacing: V goes from the triangle to the camera, wherever the camera is",
          "[culling]") {
  const Vec3 A(0, 0, 5), B(0, 1, 5), C(1, 0, 5);  // N = (0, 0, -1): faces -Z
  CHECK_FALSE(IsBackFacing(A, B, C, {0, 0, 0}));
  CHECK(IsBackFacing(A, B, C, {0, 0, 10}));  // the camera behind it
}

TEST_CASE("CullBackFaces: a cube straight ahead shows only its blue face", "[culling]") {
  // The cube at (0, 0, 7), not rotated: only the face z = -1 (triangles 4 and 5) faces
  // the camera; red (z = +1) and the four sides are culled (the sides edge-on).
  Model cube = CubeModel();
  for (Vec3& V : cube.vertices) {
    V += Vec3(0, 0, 7);
  }
  CullBackFaces(cube, kCamera);
  CHECK(ColorsOf(cube) == std::vector<Color>{cgfs::kBlue, cgfs::kBlue});
  CHECK(cube.triangles[0].v == std::array<int, 3>{5, 4, 7});
  CHECK(cube.triangles[1].v == std::array<int, 3>{5, 7, 6});
}

TEST_CASE("CullBackFaces: half the triangles of Figure 10-10's cubes are culled", "[culling]") {
  CameraSpaceScene scene = ClippedCameraSpaceScene(SceneTransformedCubes());
  REQUIRE(scene.instances.size() == 2);
  // Instance A, left of and below the camera: blue (front), yellow (left), purple (top).
  CullBackFaces(scene.instances[0].model, kCamera);
  CHECK(ColorsOf(scene.instances[0].model) == std::vector<Color>{cgfs::kBlue, cgfs::kBlue,
                                                                 cgfs::kYellow, cgfs::kYellow,
                                                                 cgfs::kPurple, cgfs::kPurple});
  // Instance B, turned 195 degrees and above the camera: red, green and the bottom, cyan.
  CullBackFaces(scene.instances[1].model, kCamera);
  CHECK(ColorsOf(scene.instances[1].model) == std::vector<Color>{cgfs::kRed, cgfs::kRed,
                                                                 cgfs::kGreen, cgfs::kGreen,
                                                                 cgfs::kCyan, cgfs::kCyan});
}

TEST_CASE("culling after clipping: the pieces of a clipped triangle face as it did", "[culling]") {
  // A small cube cut by the near plane: every triangle clipping makes faces the camera
  // exactly when the triangle it came from does, because clipping keeps the winding.
  Scene scene;
  scene.instances = {{&CubeModel(), {0.25, MakeOYRotationMatrix(30), {0.05, -0.1, 1.05}}}};
  const CameraSpaceScene clipped = ClippedCameraSpaceScene(scene);
  REQUIRE(clipped.instances.size() == 1);
  const Model& model = clipped.instances[0].model;
  REQUIRE(model.triangles.size() > CubeModel().triangles.size());  // some were split
  for (const Triangle& T : model.triangles) {
    // Each face of the cube has its own colour, and all its points one orientation.
    const Triangle& original =
        *std::find_if(CubeModel().triangles.begin(), CubeModel().triangles.end(),
                      [&](const Triangle& U) { return U.color == T.color; });
    const glm::dmat4 M = MakeTransformMatrix(scene.instances[0].transform);
    const auto at = [&](int i) {
      return cgfs::ToCartesian(M * glm::dvec4(CubeModel().vertices[i], 1));
    };
    CHECK(IsBackFacing(model.vertices[T.v[0]], model.vertices[T.v[1]], model.vertices[T.v[2]],
                       kCamera) ==
          IsBackFacing(at(original.v[0]), at(original.v[1]), at(original.v[2]), kCamera));
  }
}
