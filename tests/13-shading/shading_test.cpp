// "Flat Shading", "Gouraud Shading", "Phong Shading", UnProjectVertex, normals in the
// model and through clipping, and the sphere generator.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <utility>

#include "cases.h"
#include "checks.h"
#include "scenes.h"
#include "sphere_model.h"

using Catch::Detail::Approx;
using cgfs::Rgb8;
using cgfs::test::CheckNear;

namespace {

// A white square facing the camera at z = 5, corners (+-1, +-1, 5), normal (0, 0, -1).
Model FacingSquare() {
  const std::array<Vec3, 3> toward_camera = {Vec3(0, 0, -1), Vec3(0, 0, -1), Vec3(0, 0, -1)};
  Model square;
  square.vertices = {{-1, 1, 5}, {1, 1, 5}, {1, -1, 5}, {-1, -1, 5}};
  square.triangles = {{{0, 1, 2}, cgfs::kWhite, toward_camera},
                      {{0, 2, 3}, cgfs::kWhite, toward_camera}};
  return square;
}

// Built member by member, so that the later chapters, whose Shading and Lighting
// have more members, can run these tests too.
Shading ShadingOf(ShadingModel model, NormalSource normals, LightingTerms terms) {
  Shading shading;
  shading.model = model;
  shading.normals = normals;
  shading.terms = terms;
  return shading;
}

Surface SurfaceOf(const Color& color, double specular) {
  Surface surface;
  surface.color = color;
  surface.specular = specular;
  return surface;
}

Lighting LightingOf(std::vector<Light> lights, const Shading& shading) {
  Lighting lighting;
  lighting.lights = std::move(lights);
  lighting.shading = shading;
  return lighting;
}

Canvas RenderWith(const Scene& scene, const Shading& shading) {
  Canvas canvas(600, 600);
  RenderScene(scene, canvas, shading);
  return canvas;
}

}  // namespace

TEST_CASE("UnProjectVertex: the cases of 13-shading.json", "[shading]") {
  for (const cgfs::test::FunctionCase& c :
       cgfs::test::CasesOf("13-shading.json", "UnProjectVertex")) {
    INFO(c.Describe());
    const nlohmann::json& size = c.given.at("canvas");
    const nlohmann::json& viewport = c.given.at("viewport");
    const Vec3 P = UnProjectVertex(
        c.args.at("x").get<int>(), c.args.at("y").get<int>(),
        cgfs::test::ToNumber(c.args.at("inv_z")),
        Canvas(size.at("width").get<int>(), size.at("height").get<int>()),
        Viewport{viewport.at("width").get<double>(), viewport.at("height").get<double>(),
                 viewport.at("d").get<double>()});
    CHECK_THAT(cgfs::test::AsNumbers(P), cgfs::test::MatchesCase(c));
  }
}

TEST_CASE("ComputeTriangleNormal: the cases of 13-shading.json", "[shading]") {
  using cgfs::test::ToVector;
  for (const cgfs::test::FunctionCase& c :
       cgfs::test::CasesOf("13-shading.json", "ComputeTriangleNormal")) {
    INFO(c.Describe());
    const Vec3 N = ComputeTriangleNormal(ToVector(c.args.at("A")), ToVector(c.args.at("B")),
                                         ToVector(c.args.at("C")));
    CHECK_THAT(cgfs::test::AsNumbers(N), cgfs::test::MatchesCase(c));
  }
}

TEST_CASE("UnProjectVertex: the point a pixel shows at a given 1/z", "[shading]") {
  const Canvas canvas(600, 600);
  const Viewport viewport;
  CheckNear(UnProjectVertex(60, -30, 0.2, canvas, viewport), {0.5, -0.25, 5});
  // ProjectVertex undone: a point whose projection lands exactly on a pixel.
  const Vec3 P(1.5, -2, 6);
  const Point p = ProjectVertex(P, canvas, viewport);
  CHECK(p == Point{150, -200});
  CheckNear(UnProjectVertex(p.x, p.y, 1 / P.z, canvas, viewport), P);
}

TEST_CASE("ComputeTriangleNormal: unit, outwards for the cube's winding", "[shading]") {
  const Model& cube = CubeModel();
  for (const Triangle& T : cube.triangles) {
    const Vec3 N =
        ComputeTriangleNormal(cube.vertices[T.v[0]], cube.vertices[T.v[1]], cube.vertices[T.v[2]]);
    CheckNear(N, T.normals[0]);  // the cube's model normals are its faces' normals
  }
}

TEST_CASE("Phong shading lights a pixel with the interpolated normal made unit again",
          "[shading]") {
  // The bottom side runs from A, normal (1, 0, 0), to B, normal (0, 1, 0); midway, at
  // pixel (0, -120), the interpolated normal is (0.5, 0.5, 0), 0.707 long. A light along
  // (1, 0, 0), specular term only (s = 1): with the unit normal R = (0, 1, 0) and the
  // point is (0, -1, 5), so <R, V>/|V| = 1/sqrt(26) = 0.196, 50 of 255. The normal left
  // 0.707 long would give R = (-0.5, 0.5, 0) and 35.
  const Canvas canvas(600, 600);
  const Viewport viewport;
  const std::array<Vec3, 3> positions = {Vec3(-2, -1, 5), Vec3(2, -1, 5), Vec3(0, 2, 5)};
  const std::array<Vec3, 3> normals = {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, -1)};
  std::array<ShadedCorner, 3> corners;
  for (std::size_t k = 0; k < 3; ++k) {
    corners[k] = {positions[k], ProjectVertex(positions[k], canvas, viewport), normals[k]};
  }
  const Lighting lighting =
      LightingOf({{LightType::kDirectional, 1, {}, {1, 0, 0}}},
                 ShadingOf(ShadingModel::kPhong, NormalSource::kModel, {false, true}));
  Canvas drawn(600, 600);
  DepthBuffer depth_buffer(drawn, DepthValue::kInverseZ);
  Frame frame(drawn, depth_buffer, viewport);
  ShadePhong(corners, SurfaceOf(cgfs::kWhite, 1), lighting, frame);
  const Vec3 P = UnProjectVertex(0, -120, 0.2, drawn, viewport);
  CheckNear(P, {0, -1, 5});
  const double expected = ComputeLighting(P, glm::normalize(Vec3(0.5, 0.5, 0)), -P, 1,
                                          lighting.lights, lighting.shading.terms);
  CHECK(expected == Approx(1 / std::sqrt(26.0)));
  CHECK(drawn.GetPixel(0, -120) == Rgb8{50, 50, 50});
}

TEST_CASE("a large face lit from close by: Gouraud 0.070535 at its centre, Phong 1.0",
          "[shading]") {
  // A point light of intensity 1 at (0, 0, 4.9), 0.1 in front of the square's centre;
  // no ambient light, no specular term.
  static const Model square = FacingSquare();
  Scene scene;
  scene.instances = {{&square, {}}};
  scene.lights = {{LightType::kPoint, 1, {0, 0, 4.9}}};
  // At a corner: L = (-1, -1, -0.1), <N, L> = 0.1, |L| = sqrt(2.01).
  CHECK(ComputeLighting({1, 1, 5}, {0, 0, -1}, {-1, -1, -5}, -1, scene.lights) == Approx(0.070535));
  const LightingTerms diffuse{true, false};
  const Canvas gouraud =
      RenderWith(scene, ShadingOf(ShadingModel::kGouraud, NormalSource::kModel, diffuse));
  const Canvas phong =
      RenderWith(scene, ShadingOf(ShadingModel::kPhong, NormalSource::kModel, diffuse));
  CHECK(gouraud.GetPixel(0, 0) == Rgb8{18, 18, 18});    // 255 x 0.070535 = 17.99
  CHECK(phong.GetPixel(0, 0) == Rgb8{255, 255, 255});   // 255 x 1.0
  CHECK(gouraud.GetPixel(60, 60) == Rgb8{18, 18, 18});  // Gouraud: the same everywhere
  CHECK(phong.GetPixel(60, 60).r < 255);                // Phong: darker away from the light
}

TEST_CASE("Phong interpolates the normal, Gouraud the light", "[shading]") {
  // A triangle whose corner normals turn from (1, 0, 0) to (0, 1, 0); a directional
  // light along (1, 1, 0). Gouraud: 1/sqrt(2) at both corners, so 0.707 between them.
  // Phong: the normal midway is (1, 1, 0)/sqrt(2), the light's own direction: 1.0.
  const Lighting gouraud =
      LightingOf({{LightType::kDirectional, 1, {}, {1, 1, 0}}},
                 ShadingOf(ShadingModel::kGouraud, NormalSource::kModel, {true, false}));
  Lighting phong = gouraud;
  phong.shading.model = ShadingModel::kPhong;
  const Canvas canvas(600, 600);
  const Viewport viewport;
  const std::array<Vec3, 3> positions = {Vec3(-2, -1, 5), Vec3(2, -1, 5), Vec3(0, 2, 5)};
  const std::array<Vec3, 3> normals = {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0.5, 0.5, 0)};
  std::array<ShadedCorner, 3> corners;
  for (int k = 0; k < 3; ++k) {
    corners[k] = {positions[k], ProjectVertex(positions[k], canvas, viewport), normals[k]};
  }
  const auto shaded = [&](const Lighting& lighting) {
    Canvas drawn(600, 600);
    DepthBuffer depth_buffer(drawn, DepthValue::kInverseZ);
    Frame frame(drawn, depth_buffer, viewport);
    ShadeTriangle(corners, SurfaceOf(cgfs::kWhite, -1), lighting, frame);
    // Just above the midpoint of the bottom side, (0, -1, 5).
    return int{drawn.GetPixel(0, -119).r};
  };
  CHECK(shaded(gouraud) >= 180);  // 255 x 0.7071, and a pixel's worth towards the top
  CHECK(shaded(gouraud) <= 182);
  CHECK(shaded(phong) == 255);
}

TEST_CASE("flat shading: a face's two triangles differ under a point light only", "[shading]") {
  // The two triangles of a square share their normal but not their centroid: a point
  // light reaches the centroids at different angles, a directional light at the same.
  const std::array<Vec3, 3> N = {Vec3(0, 0, -1), Vec3(0, 0, -1), Vec3(0, 0, -1)};
  const std::array<ShadedCorner, 3> first = {
      {{{-1, 1, 5}, {}, N[0]}, {{1, 1, 5}, {}, N[1]}, {{1, -1, 5}, {}, N[2]}}};
  const std::array<ShadedCorner, 3> second = {
      {{{-1, 1, 5}, {}, N[0]}, {{1, -1, 5}, {}, N[1]}, {{-1, -1, 5}, {}, N[2]}}};
  const Shading flat = ShadingOf(ShadingModel::kFlat, NormalSource::kTriangle, {true, false});
  const Lighting point = LightingOf({{LightType::kPoint, 0.6, {3, 0, 2}}}, flat);
  const Lighting directional = LightingOf({{LightType::kDirectional, 0.6, {}, {1, 0, -1}}}, flat);
  CHECK(std::abs(FlatIllumination(first, 50, point) - FlatIllumination(second, 50, point)) > 0.01);
  CHECK(FlatIllumination(first, 50, directional) ==
        Approx(FlatIllumination(second, 50, directional)).epsilon(1e-12));
}

TEST_CASE("GenerateSphere(15): 240 vertices, 450 triangles, 420 of them real, no seam",
          "[sphere]") {
  const Model sphere = GenerateSphere(15, cgfs::kGreen);
  CHECK(sphere.vertices.size() == 240);
  CHECK(sphere.triangles.size() == 450);
  int real = 0;
  std::map<std::pair<int, int>, int> edges;  // each edge of a closed surface: twice
  for (const Triangle& T : sphere.triangles) {
    const Vec3& A = sphere.vertices[T.v[0]];
    const Vec3& B = sphere.vertices[T.v[1]];
    const Vec3& C = sphere.vertices[T.v[2]];
    for (int k = 0; k < 3; ++k) {
      CheckNear(T.normals[k], sphere.vertices[T.v[k]]);  // the normal is the position
    }
    const Vec3 cross = glm::cross(B - A, C - A);
    if (glm::length(cross) < 1e-12) {
      continue;  // two corners on a pole
    }
    ++real;
    CHECK(glm::dot(cross, A + B + C) > 0);  // wound outwards
    for (int k = 0; k < 3; ++k) {
      // Corners on a pole share a position: name each vertex by its position.
      const auto id = [&](int i) {
        const Vec3& V = sphere.vertices[T.v[i]];
        return std::abs(V.y) == 1 ? (V.y > 0 ? -1 : -2) : T.v[i];
      };
      const int a = id(k);
      const int b = id((k + 1) % 3);
      ++edges[{std::min(a, b), std::max(a, b)}];
    }
  }
  CHECK(real == 420);
  for (const auto& [edge, count] : edges) {
    INFO("edge " << edge.first << "-" << edge.second);
    CHECK(count == 2);
  }
  const BoundingSphere bounds = ComputeBoundingSphere(sphere.vertices);
  CheckNear(bounds.center, {0, 0, 0}, 1e-9);
  CHECK(bounds.radius == Approx(1));
}

TEST_CASE("TransformToCameraSpace turns the normals and keeps them unit", "[shading]") {
  static const Model cube = CubeModel();
  const Instance I{&cube, {2, MakeOYRotationMatrix(90), {5, 5, 5}}};
  const CameraSpaceInstance moved = TransformToCameraSpace(I, MakeTransformMatrix(I.transform));
  // The red face's normal (0, 0, 1): OY(90) turns +Z into -X; not moved, not scaled.
  CheckNear(moved.model.triangles[0].normals[0], {-1, 0, 0});
  CHECK(moved.model.specular == cube.specular);
}

TEST_CASE("ClipTriangle interpolates the normals of the new corners", "[shading]") {
  // One vertex in front of the near plane: B' = A + 2/3 (B - A), C' = A + 2/3 (C - A).
  std::vector<Vec3> vertices = {{0, 0, 3}, {2, 0, 0}, {0, 2, 0}};
  const Triangle T{{0, 1, 2}, cgfs::kRed, {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)}};
  const std::vector<Triangle> clipped = ClipTriangle(T, {{0, 0, 1}, -1}, vertices);
  REQUIRE(clipped.size() == 1);
  CheckNear(vertices[clipped[0].v[1]], {4.0 / 3, 0, 1});
  CheckNear(clipped[0].normals[0], {1, 0, 0});
  CheckNear(clipped[0].normals[1], {1.0 / 3, 2.0 / 3, 0});
  CheckNear(clipped[0].normals[2], {1.0 / 3, 0, 2.0 / 3});
}
