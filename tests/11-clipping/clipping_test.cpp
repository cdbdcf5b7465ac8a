// The clipping volume, signed distances, bounding spheres, and clipping
// triangles against a plane.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <optional>
#include <vector>

#include "cases.h"
#include "checks.h"
#include "printing.h"
#include "scenes.h"

using Catch::Detail::Approx;
using cgfs::test::CheckNear;
using cgfs::test::IsSameImageAs;

namespace {

const Plane kNear{{0, 0, 1}, -1};

// {"normal": [x, y, z], "D": D}.
Plane PlaneOfCase(const nlohmann::json& plane) {
  return {cgfs::test::ToVector(plane.at("normal")), cgfs::test::ToNumber(plane.at("D"))};
}

Plane PlaneNamed(int index) {
  return ClippingPlanes(1)[static_cast<std::size_t>(index)];
}

// The triangle's vertices, in its own order.
std::array<Vec3, 3> Corners(const Triangle& T, const std::vector<Vec3>& vertices) {
  return {vertices[static_cast<std::size_t>(T.v[0])], vertices[static_cast<std::size_t>(T.v[1])],
          vertices[static_cast<std::size_t>(T.v[2])]};
}

Vec3 Normal(const std::array<Vec3, 3>& corners) {
  return glm::cross(corners[1] - corners[0], corners[2] - corners[0]);
}

// Two vectors point the same way when their cross product vanishes and their dot
// product is positive.
void CheckSameDirection(const Vec3& a, const Vec3& b) {
  CHECK(glm::length(glm::cross(a, b)) == Approx(0).margin(1e-9));
  CHECK(glm::dot(a, b) > 0);
}

}  // namespace

TEST_CASE("ClippingPlanes: the five planes of the clipping volume have unit normals",
          "[clipping]") {
  const std::vector<Plane> planes = ClippingPlanes(1);
  REQUIRE(planes.size() == 5);
  for (const Plane& plane : planes) {
    CHECK(glm::length(plane.normal) == Approx(1));
  }
  CHECK(planes[0].normal == Vec3(0, 0, 1));
  CHECK(planes[0].D == -1);
  // Every plane has the inside of the volume on its positive side.
  for (const Plane& plane : planes) {
    CHECK(SignedDistance(plane, {0, 0, 5}) > 0);
  }
}

TEST_CASE("SignedDistance: the cases of 11-clipping.json", "[clipping]") {
  // The first two: the left plane's hand-worked 3.535534 and -0.707107.
  for (const cgfs::test::FunctionCase& c :
       cgfs::test::CasesOf("11-clipping.json", "SignedDistance")) {
    INFO(c.Describe());
    const double distance =
        SignedDistance(PlaneOfCase(c.args.at("plane")), cgfs::test::ToVector(c.args.at("vertex")));
    CHECK_THAT(cgfs::test::AsNumbers(distance), cgfs::test::MatchesCase(c));
  }
}

TEST_CASE("SignedDistance: ClippingPlanes' left plane, and sideways along the near plane",
          "[clipping]") {
  const Plane left = PlaneNamed(1);
  CHECK(SignedDistance(left, {0, 0, 5}) == Approx(3.535534));
  CHECK(SignedDistance(left, {-3, 0, 2}) == Approx(-0.707107));
  CHECK(SignedDistance(kNear, {5, 5, 3}) == 2);  // sideways does not matter to the near plane
}

TEST_CASE("Intersection: the cases of 11-clipping.json", "[clipping]") {
  for (const cgfs::test::FunctionCase& c :
       cgfs::test::CasesOf("11-clipping.json", "Intersection")) {
    INFO(c.Describe());
    const Vec3 Q =
        Intersection(cgfs::test::ToVector(c.args.at("A")), cgfs::test::ToVector(c.args.at("B")),
                     PlaneOfCase(c.args.at("plane")));
    CHECK_THAT(cgfs::test::AsNumbers(Q), cgfs::test::MatchesCase(c));
  }
}

TEST_CASE("IntersectionT: the t of a segment's crossing, for every attribute", "[clipping]") {
  const Vec3 A(0, 0, 0.5);
  const Vec3 B(0, 0, 3);
  CHECK(IntersectionT(A, B, kNear) == Approx(0.2));
  // Any attribute goes along with the same t: 10 at A and 20 at B give 12 at Q.
  CHECK(glm::mix(10.0, 20.0, IntersectionT(A, B, kNear)) == Approx(12));
  // The same crossing, found from the other end.
  CHECK(IntersectionT(B, A, kNear) == Approx(0.8));
}

TEST_CASE("ClipTriangle: the cases of 11-clipping.json", "[clipping]") {
  for (const cgfs::test::FunctionCase& c :
       cgfs::test::CasesOf("11-clipping.json", "ClipTriangle")) {
    INFO(c.Describe());
    std::vector<Vec3> vertices;
    for (const nlohmann::json& vertex : c.args.at("vertices")) {
      vertices.push_back(cgfs::test::ToVector(vertex));
    }
    const nlohmann::json& triangle = c.args.at("triangle");
    const Triangle T{triangle.at("v").get<std::array<int, 3>>(),
                     cgfs::test::ToColor(triangle.at("color"))};
    std::vector<double> corners;  // each triangle's corners, in its order
    for (const Triangle& piece : ClipTriangle(T, PlaneOfCase(c.args.at("plane")), vertices)) {
      for (const Vec3& corner : Corners(piece, vertices)) {
        corners.insert(corners.end(), {corner.x, corner.y, corner.z});
      }
    }
    CHECK_THAT(corners, cgfs::test::MatchesCase(c));
  }
}

TEST_CASE("ClipTriangle: wholly in front, wholly behind", "[clipping]") {
  std::vector<Vec3> vertices = {{0, 0, 2}, {1, 0, 3}, {0, 1, 1}, {0, 0, -2}, {1, 0, 0.5}};
  const Triangle in_front{{0, 1, 2}, cgfs::kRed};  // z = 1 counts as in front
  const std::vector<Triangle> kept = ClipTriangle(in_front, kNear, vertices);
  REQUIRE(kept.size() == 1);
  CHECK(kept[0].v == in_front.v);
  const Triangle behind{{3, 4, 3}, cgfs::kRed};
  CHECK(ClipTriangle(behind, kNear, vertices).empty());
  CHECK(vertices.size() == 5);  // nothing new
}

TEST_CASE("ClipTriangle: one vertex in front gives one smaller triangle", "[clipping]") {
  std::vector<Vec3> vertices = {{0, 0, 3}, {2, 0, 0}, {0, 2, 0}};
  const Triangle T{{0, 1, 2}, cgfs::kGreen};
  const std::vector<Triangle> clipped = ClipTriangle(T, kNear, vertices);
  REQUIRE(clipped.size() == 1);
  CHECK(clipped[0].color == cgfs::kGreen);
  const std::array<Vec3, 3> corners = Corners(clipped[0], vertices);
  CheckNear(corners[0], {0, 0, 3});
  CheckNear(corners[1], {4.0 / 3, 0, 1});
  CheckNear(corners[2], {0, 4.0 / 3, 1});
  CheckSameDirection(Normal(corners), Normal(Corners(T, vertices)));
}

TEST_CASE("ClipTriangle: two vertices in front give two triangles", "[clipping]") {
  std::vector<Vec3> vertices = {{-1, 0, 3}, {1, 0, 3}, {0, 1, 0}};
  const Triangle T{{0, 1, 2}, cgfs::kBlue};
  const std::vector<Triangle> clipped = ClipTriangle(T, kNear, vertices);
  REQUIRE(clipped.size() == 2);
  // C = v2 is behind: A' on AC, B' on BC; the output is (v0, v1, A'), (A', v1, B').
  const std::array<Vec3, 3> first = Corners(clipped[0], vertices);
  const std::array<Vec3, 3> second = Corners(clipped[1], vertices);
  const Vec3 A_prime(-1.0 / 3, 2.0 / 3, 1);
  const Vec3 B_prime(1.0 / 3, 2.0 / 3, 1);
  CheckNear(first[0], {-1, 0, 3});
  CheckNear(first[1], {1, 0, 3});
  CheckNear(first[2], A_prime);
  CheckNear(second[0], A_prime);
  CheckNear(second[1], {1, 0, 3});
  CheckNear(second[2], B_prime);
  // Both keep the original's winding: their normals point along (0, 6, 2).
  CheckSameDirection(Normal(first), {0, 6, 2});
  CheckSameDirection(Normal(second), {0, 6, 2});
  CheckSameDirection(Normal(Corners(T, vertices)), {0, 6, 2});
}

TEST_CASE("ClipTriangle keeps the winding whichever vertex is behind", "[clipping]") {
  // Rotate the vertex order: the one behind the plane moves through every position,
  // and the outputs always turn the same way as the input.
  const std::vector<Vec3> base = {{-1, 0, 3}, {1, 0, 3}, {0, 1, 0},
                                  {0, 0, 3},  {2, 0, 0}, {0, 2, 0}};
  const std::array<std::array<int, 3>, 6> orders = {
      {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {3, 4, 5}, {4, 5, 3}, {5, 3, 4}}};
  for (const auto& order : orders) {
    std::vector<Vec3> vertices = base;
    const Triangle T{order, cgfs::kRed};
    const Vec3 original = Normal(Corners(T, vertices));
    const std::vector<Triangle> clipped = ClipTriangle(T, kNear, vertices);
    REQUIRE_FALSE(clipped.empty());
    for (const Triangle& piece : clipped) {
      const std::array<Vec3, 3> corners = Corners(piece, vertices);
      CheckSameDirection(Normal(corners), original);
      for (const Vec3& corner : corners) {
        CHECK(SignedDistance(kNear, corner) >= -1e-12);
      }
    }
  }
}

TEST_CASE("ClipTrianglesAgainstPlane joins the lists instead of nesting them", "[clipping]") {
  std::vector<Vec3> vertices = {{-1, 0, 3}, {1, 0, 3}, {0, 1, 0}, {0, 0, 3}, {2, 0, 0}, {0, 2, 0}};
  const std::vector<Triangle> triangles = {{{0, 1, 2}, cgfs::kRed}, {{3, 4, 5}, cgfs::kBlue}};
  const std::vector<Triangle> clipped = ClipTrianglesAgainstPlane(triangles, kNear, vertices);
  CHECK(clipped.size() == 3);  // two from the first, one from the second
  CHECK(vertices.size() == 6 + 4);
}

TEST_CASE("ComputeBoundingSphere: the cases of 11-clipping.json", "[clipping]") {
  for (const cgfs::test::FunctionCase& c :
       cgfs::test::CasesOf("11-clipping.json", "ComputeBoundingSphere")) {
    INFO(c.Describe());
    std::vector<Vec3> vertices;
    for (const nlohmann::json& vertex : c.args.at("vertices")) {
      vertices.push_back(cgfs::test::ToVector(vertex));
    }
    const BoundingSphere sphere = ComputeBoundingSphere(vertices);
    const Vec3& centre = sphere.center;
    CHECK_THAT((std::vector<double>{centre.x, centre.y, centre.z, sphere.radius}),
               cgfs::test::MatchesCase(c));
  }
}

TEST_CASE("ComputeBoundingSphere: the bounding sphere of the cube: centre 0, radius sqrt 3",
          "[clipping]") {
  const BoundingSphere sphere = ComputeBoundingSphere(CubeModel().vertices);
  CheckNear(sphere.center, {0, 0, 0});
  CHECK(sphere.radius == Approx(std::sqrt(3.0)));
}

TEST_CASE("ClipInstance: instance A of figure 10-10 is accepted whole", "[clipping]") {
  const Scene scene = SceneTransformedCubes();
  const glm::dmat4 M = MakeCameraMatrix(scene.camera.position, scene.camera.orientation) *
                       MakeTransformMatrix(scene.instances[0].transform);
  const CameraSpaceInstance A = TransformToCameraSpace(scene.instances[0], M);
  CheckNear(A.bounding_sphere.center, {-1.200962, -1, 5.080127});
  CHECK(A.bounding_sphere.radius == Approx(0.75 * std::sqrt(3.0)));  // scale included
  // near, left, right, bottom, top
  const double expected[] = {4.080127, 2.743, 4.441, 2.885, 4.299};
  for (int i = 0; i < 5; ++i) {
    CHECK(SignedDistance(PlaneNamed(i), A.bounding_sphere.center) ==
          Approx(expected[i]).margin(1e-3));
    CHECK(SignedDistance(PlaneNamed(i), A.bounding_sphere.center) > A.bounding_sphere.radius);
  }
  const std::optional<CameraSpaceInstance> clipped = ClipInstance(A, ClippingPlanes(1));
  REQUIRE(clipped);
  CHECK(clipped->model.vertices.size() == 8);  // untouched: no triangle needed clipping
  CHECK(clipped->model.triangles.size() == 12);
}

TEST_CASE("ClipInstance: the cube behind the camera is rejected whole", "[clipping]") {
  const Scene scene = SceneWithCubeBehindCamera();
  const glm::dmat4 M = MakeCameraMatrix(scene.camera.position, scene.camera.orientation) *
                       MakeTransformMatrix(scene.instances[2].transform);
  const CameraSpaceInstance behind = TransformToCameraSpace(scene.instances[2], M);
  CheckNear(behind.bounding_sphere.center, {8.598076, -1, -8.892305});
  CHECK(SignedDistance(PlaneNamed(0), behind.bounding_sphere.center) == Approx(-9.892305));
  CHECK_FALSE(ClipInstanceAgainstPlane(behind, PlaneNamed(0)));
  CHECK_FALSE(ClipInstance(behind, ClippingPlanes(1)));
}

TEST_CASE("ClipScene keeps the instances that survive", "[clipping]") {
  const Scene scene = SceneWithCubeBehindCamera();
  const glm::dmat4 M_camera = MakeCameraMatrix(scene.camera.position, scene.camera.orientation);
  CameraSpaceScene camera_space_scene;
  for (const Instance& I : scene.instances) {
    camera_space_scene.instances.push_back(
        TransformToCameraSpace(I, M_camera * MakeTransformMatrix(I.transform)));
  }
  CHECK(ClipScene(camera_space_scene, ClippingPlanes(1)).instances.size() == 2);
}

TEST_CASE("ClipInstance: a cube across the near plane is clipped: every vertex ends up at z >= d",
          "[clipping]") {
  const Scene scene = SceneCubeCutByNearPlane();
  const CameraSpaceInstance cube =
      TransformToCameraSpace(scene.instances[0], MakeTransformMatrix(scene.instances[0].transform));
  const double d = SignedDistance(PlaneNamed(0), cube.bounding_sphere.center);
  CHECK(std::abs(d) <= cube.bounding_sphere.radius);  // the sphere straddles the plane
  const std::optional<CameraSpaceInstance> clipped = ClipInstance(cube, ClippingPlanes(1));
  REQUIRE(clipped);
  CHECK(clipped->model.vertices.size() > 8);  // new vertices on the cut
  CHECK(clipped->model.triangles.size() > 0);
  for (const Triangle& T : clipped->model.triangles) {
    for (const Vec3& corner : Corners(T, clipped->model.vertices)) {
      CHECK(corner.z >= 1 - 1e-12);
    }
  }
}

TEST_CASE("a cube around the camera: only its face on the near plane is left", "[clipping]") {
  // The untransformed cube surrounds the camera (chapter 10 could not draw it). Its
  // face z = +1 lies on the near plane, at x, y = +-600 pixels; everything else is
  // behind the plane, or reduced to slivers of no area along that face's edges.
  Scene scene;
  scene.instances = {{&CubeModel(), {}}};
  Canvas canvas(600, 600);
  RenderScene(scene, canvas);
  Canvas front_face(600, 600);
  DrawWireframeTriangle({600, 600}, {-600, 600}, {-600, -600}, cgfs::kRed, front_face);
  DrawWireframeTriangle({600, 600}, {-600, -600}, {600, -600}, cgfs::kRed, front_face);
  CHECK_THAT(canvas.GetImage(), IsSameImageAs(front_face.GetImage()));
}

TEST_CASE("a cube behind the camera draws nothing, not an upside-down image", "[clipping]") {
  Scene scene;
  scene.instances = {{&CubeModel(), {1, glm::dmat4(1.0), {0.5, 0.5, -5}}}};
  Canvas canvas(600, 600);
  RenderScene(scene, canvas);
  CHECK_THAT(canvas.GetImage(), IsSameImageAs(Canvas(600, 600).GetImage()));
}

TEST_CASE("geometry reaching from behind the camera is drawn only where it is in front",
          "[clipping]") {
  // A long box from z = -4 to z = 6: its far end is visible, its near end is cut at
  // the near plane, and every vertex that reaches ProjectVertex has z >= d.
  Scene scene;
  scene.instances = {{&CubeModel(), {5, glm::dmat4(1.0), {0, 0, 1}}}};
  const glm::dmat4 M = MakeTransformMatrix(scene.instances[0].transform);
  CameraSpaceScene camera_space_scene{{TransformToCameraSpace(scene.instances[0], M)}};
  const CameraSpaceScene clipped = ClipScene(camera_space_scene, ClippingPlanes(1));
  REQUIRE(clipped.instances.size() == 1);
  CHECK_FALSE(clipped.instances[0].model.triangles.empty());
  for (const Triangle& T : clipped.instances[0].model.triangles) {
    for (const Vec3& corner : Corners(T, clipped.instances[0].model.vertices)) {
      CHECK(corner.z >= 1 - 1e-12);
    }
  }
  Canvas canvas(600, 600);
  RenderScene(scene, canvas);
  CHECK(canvas.GetImage() != Canvas(600, 600).GetImage());
}
