// Spec §7.4 to §12.4: Interpolate, DrawLine, the triangles, the projection, the transforms
// and clipping, with exact outputs.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include "pixels.h"
#include "printing.h"
#include "rasterizer.h"

using cgfs::test::DrawnPixels;
using Pixels = std::set<std::pair<int, int>>;

namespace {

Pixels LinePixels(Point P0, Point P1) {
  Canvas canvas(600, 600);
  DrawLine(P0, P1, cgfs::kBlack, canvas);
  return DrawnPixels(canvas);
}

// Exactly one pixel for every step along the major axis, each next to the one
// before it (8-connected): no gaps, no doubled pixels.
void CheckOnePixelPerStep(const Pixels& pixels, Point P0, Point P1) {
  const bool x_major = std::abs(P1.x - P0.x) > std::abs(P1.y - P0.y);
  const int from = x_major ? std::min(P0.x, P1.x) : std::min(P0.y, P1.y);
  const int to = x_major ? std::max(P0.x, P1.x) : std::max(P0.y, P1.y);
  REQUIRE(pixels.size() == static_cast<std::size_t>(to - from + 1));
  std::vector<int> minor(static_cast<std::size_t>(to - from + 1), 0);
  std::vector<int> count(minor.size(), 0);
  for (const auto& [x, y] : pixels) {
    const int major = x_major ? x : y;
    REQUIRE(major >= from);
    REQUIRE(major <= to);
    ++count[static_cast<std::size_t>(major - from)];
    minor[static_cast<std::size_t>(major - from)] = x_major ? y : x;
  }
  for (std::size_t i = 0; i < count.size(); ++i) {
    CHECK(count[i] == 1);
    if (i > 0) {
      CHECK(std::abs(minor[i] - minor[i - 1]) <= 1);
    }
  }
}

}  // namespace

TEST_CASE("Interpolate returns one value per integer step", "[interpolate]") {
  CHECK(Interpolate(0, 0, 4, 2) == std::vector<double>{0, 0.5, 1, 1.5, 2});
  CHECK(Interpolate(0, 10, 2, 0) == std::vector<double>{10, 5, 0});
  CHECK(Interpolate(-2, 1, 1, -5) == std::vector<double>{1, -1, -3, -5});
}

TEST_CASE("Interpolate with i0 == i1 returns [d0]", "[interpolate]") {
  CHECK(Interpolate(3, 7, 3, 9) == std::vector<double>{7});
}

TEST_CASE("Interpolate over a descending range returns nothing", "[interpolate]") {
  CHECK(Interpolate(5, 0, 3, 1).empty());
}

TEST_CASE("Interpolate does not drift: the last value is d1", "[interpolate]") {
  // Accumulating d += a would add up rounding errors over hundreds of steps.
  for (const auto& [i1, d1] : {std::pair{500, 220.0}, std::pair{440, 220.0}, std::pair{301, 7.0}}) {
    const std::vector<double> values = Interpolate(0, 0, i1, d1);
    REQUIRE(values.size() == static_cast<std::size_t>(i1 + 1));
    CHECK(values.back() == d1);
  }
}

TEST_CASE("DrawLine: the shallow segment of the chapter", "[draw-line]") {
  const Pixels pixels = LinePixels({-200, -100}, {240, 120});
  CHECK(pixels.size() == 441);
  CHECK(pixels.count({-200, -100}) == 1);
  CHECK(pixels.count({0, 0}) == 1);
  CHECK(pixels.count({240, 120}) == 1);
  // At x = -1 the exact y is -0.5: truncation toward zero gives 0 (floor would give -1).
  CHECK(pixels.count({-1, 0}) == 1);
  CHECK(pixels.count({-1, -1}) == 0);
  CheckOnePixelPerStep(pixels, {-200, -100}, {240, 120});
}

TEST_CASE("DrawLine: the steep segment of the chapter", "[draw-line]") {
  const Pixels pixels = LinePixels({-50, -200}, {60, 240});
  CHECK(pixels.size() == 441);
  CHECK(pixels.count({-50, -200}) == 1);
  CHECK(pixels.count({60, 240}) == 1);
  CHECK(pixels.count({0, 0}) == 1);
  CHECK(pixels.count({0, 1}) == 1);
  CheckOnePixelPerStep(pixels, {-50, -200}, {60, 240});
}

TEST_CASE("DrawLine: horizontal and vertical segments", "[draw-line]") {
  const Pixels horizontal = LinePixels({-10, 5}, {10, 5});
  CHECK(horizontal.size() == 21);
  CheckOnePixelPerStep(horizontal, {-10, 5}, {10, 5});
  const Pixels vertical = LinePixels({3, -7}, {3, 7});
  CHECK(vertical.size() == 15);
  CheckOnePixelPerStep(vertical, {3, -7}, {3, 7});
}

TEST_CASE("DrawLine: reversed end points draw the same pixels", "[draw-line]") {
  const Point cases[][2] = {{{-200, -100}, {240, 120}}, {{-50, -200}, {60, 240}},
                            {{0, 0}, {50, 100}},        {{0, 0}, {100, 50}},
                            {{-30, 40}, {30, -40}},     {{10, -3}, {-290, 1}}};
  for (const auto& segment : cases) {
    CHECK(LinePixels(segment[0], segment[1]) == LinePixels(segment[1], segment[0]));
    CheckOnePixelPerStep(LinePixels(segment[1], segment[0]), segment[0], segment[1]);
  }
}

TEST_CASE("DrawLine: a zero-length segment is one pixel", "[draw-line]") {
  CHECK(LinePixels({7, -3}, {7, -3}) == Pixels{{7, -3}});
}

TEST_CASE("DrawLine: a 45-degree segment, where |dx| == |dy|", "[draw-line]") {
  const Pixels pixels = LinePixels({-5, -5}, {5, 5});
  CHECK(pixels.size() == 11);
  for (int i = -5; i <= 5; ++i) {
    CHECK(pixels.count({i, i}) == 1);
  }
}

namespace {

constexpr Point kP0{-200, -250}, kP1{200, 50}, kP2{20, 250};

Pixels FilledPixels(Point P0, Point P1, Point P2) {
  Canvas canvas(600, 600);
  DrawFilledTriangle(P0, P1, P2, cgfs::kBlack, canvas);
  return DrawnPixels(canvas);
}

// The x extent of row y of a pixel set: (first, last, count).
std::tuple<int, int, int> Row(const Pixels& pixels, int y) {
  int first = 1 << 30;
  int last = -(1 << 30);
  int count = 0;
  for (const auto& [x, row] : pixels) {
    if (row == y) {
      first = std::min(first, x);
      last = std::max(last, x);
      ++count;
    }
  }
  return {first, last, count};
}

}  // namespace

TEST_CASE("the edge lists of the chapter's triangle", "[triangle]") {
  // After sorting, y0 = -250, y1 = 50, y2 = 250.
  std::vector<double> x01 = Interpolate(-250, -200, 50, 200);
  const std::vector<double> x12 = Interpolate(50, 200, 250, 20);
  const std::vector<double> x02 = Interpolate(-250, -200, 250, 20);
  CHECK(x02.size() == 501);
  CHECK(x01.size() == 301);
  CHECK(x12.size() == 201);
  x01.pop_back();
  x01.insert(x01.end(), x12.begin(), x12.end());
  CHECK(x01.size() == 501);
  // m = 250: x02 is the left side there.
  CHECK(x02[250] == Approx(-90));
  CHECK(x01[250] == Approx(133.333333));
}

TEST_CASE("DrawFilledTriangle: rows and the pixel count of the chapter's triangle", "[triangle]") {
  const Pixels pixels = FilledPixels(kP0, kP1, kP2);
  CHECK(pixels.size() == 67215);
  CHECK(Row(pixels, 0) == std::tuple{-90, 133, 224});
  CHECK(Row(pixels, 250) == std::tuple{20, 20, 1});
  CHECK(Row(pixels, -250) == std::tuple{-200, -200, 1});
  CHECK(Row(pixels, 50) == std::tuple{-68, 200, 269});
  CHECK(std::get<2>(Row(pixels, 251)) == 0);
  CHECK(std::get<2>(Row(pixels, -251)) == 0);
}

TEST_CASE("DrawFilledTriangle: every order of the vertices gives the same pixels", "[triangle]") {
  const Pixels expected = FilledPixels(kP0, kP1, kP2);
  CHECK(FilledPixels(kP0, kP2, kP1) == expected);
  CHECK(FilledPixels(kP1, kP0, kP2) == expected);
  CHECK(FilledPixels(kP1, kP2, kP0) == expected);
  CHECK(FilledPixels(kP2, kP0, kP1) == expected);
  CHECK(FilledPixels(kP2, kP1, kP0) == expected);
}

TEST_CASE("DrawFilledTriangle: a flat top or a flat bottom", "[triangle]") {
  // y1 == y2 and y0 == y1: either of the other sides may be the "long" one.
  const Pixels flat_top = FilledPixels({0, 0}, {-10, 10}, {10, 10});
  CHECK(Row(flat_top, 10) == std::tuple{-10, 10, 21});
  CHECK(Row(flat_top, 0) == std::tuple{0, 0, 1});
  CHECK(flat_top.size() == 121);  // 1 + 3 + ... + 21
  const Pixels flat_bottom = FilledPixels({-10, 0}, {10, 0}, {0, 10});
  CHECK(Row(flat_bottom, 0) == std::tuple{-10, 10, 21});
  CHECK(flat_bottom.size() == 121);
}

TEST_CASE("DrawFilledTriangle: degenerate triangles draw without crashing", "[triangle]") {
  // All three on one row: one row, from the first two vertices after sorting.
  const Pixels flat = FilledPixels({-5, 3}, {5, 3}, {0, 3});
  CHECK(flat.size() == 11);
  CHECK(Row(flat, 3) == std::tuple{-5, 5, 11});
  // Two equal vertices: a line-like set along the remaining side.
  const Pixels sliver = FilledPixels({0, 0}, {0, 0}, {10, 20});
  CHECK(sliver.size() == 21);
  CHECK(sliver.count({0, 0}) == 1);
  CHECK(sliver.count({10, 20}) == 1);
  // All three equal: a single pixel.
  CHECK(FilledPixels({4, 4}, {4, 4}, {4, 4}) == Pixels{{4, 4}});
  // Collinear but not horizontal.
  const Pixels collinear = FilledPixels({0, 0}, {5, 10}, {10, 20});
  CHECK(collinear.size() == 21);
}

TEST_CASE("DrawWireframeTriangle draws the three sides", "[triangle]") {
  Canvas canvas(600, 600);
  DrawWireframeTriangle(kP0, kP1, kP2, cgfs::kBlack, canvas);
  Canvas sides(600, 600);
  DrawLine(kP0, kP1, cgfs::kBlack, sides);
  DrawLine(kP1, kP2, cgfs::kBlack, sides);
  DrawLine(kP2, kP0, cgfs::kBlack, sides);
  CHECK(DrawnPixels(canvas) == DrawnPixels(sides));
  CHECK(DrawnPixels(canvas).count({-200, -250}) == 1);
  CHECK(DrawnPixels(canvas).count({200, 50}) == 1);
  CHECK(DrawnPixels(canvas).count({20, 250}) == 1);
}

namespace {

Pixels ShadedPixels(Point P0, Point P1, Point P2) {
  Canvas canvas(600, 600);
  DrawShadedTriangle(P0, P1, P2, cgfs::kBlack, canvas);
  return DrawnPixels(canvas);
}

Canvas Shaded(Point P0, Point P1, Point P2) {
  Canvas canvas(600, 600);
  DrawShadedTriangle(P0, P1, P2, cgfs::kGreen, canvas);
  return canvas;
}

constexpr Point kShaded0{-200, -250, 0.3}, kShaded1{200, 50, 0.1}, kShaded2{20, 250, 1.0};

}  // namespace

TEST_CASE("the h lists of the chapter's triangle", "[shaded]") {
  std::vector<double> h01 = Interpolate(-250, 0.3, 50, 0.1);
  const std::vector<double> h12 = Interpolate(50, 0.1, 250, 1.0);
  const std::vector<double> h02 = Interpolate(-250, 0.3, 250, 1.0);
  h01.pop_back();
  h01.insert(h01.end(), h12.begin(), h12.end());
  // Row y = 0 (index 250): x02 is the left side, so h_left comes from h02.
  CHECK(h02[250] == Approx(0.65));
  CHECK(h01[250] == Approx(0.133333));
}

TEST_CASE("DrawShadedTriangle: pinned intensities", "[shaded]") {
  const Canvas canvas = Shaded(kShaded0, kShaded1, kShaded2);
  // Inside the row y = 0, h runs from 0.65 at x = -90 to 0.133 at x = 133.
  CHECK(canvas.GetPixel(0, 0) == cgfs::Rgb8{0, 113, 0});    // h = 0.441480, raw 112.577
  CHECK(canvas.GetPixel(-90, 0) == cgfs::Rgb8{0, 166, 0});  // raw 165.75
  CHECK(canvas.GetPixel(133, 0) == cgfs::Rgb8{0, 34, 0});
  CHECK(canvas.GetPixel(0, 100) == cgfs::Rgb8{0, 174, 0});  // raw 174.313
  // The vertices keep their own h.
  CHECK(canvas.GetPixel(20, 250) == cgfs::Rgb8{0, 255, 0});
  // 255 * 0.3 = 76.5 and 255 * 0.1 = 25.5 are rounding ties: the interpolated h
  // may end a hair either side of the vertex's own, so either neighbour is right.
  CHECK(canvas.GetPixel(-200, -250).g >= 76);
  CHECK(canvas.GetPixel(-200, -250).g <= 77);
  CHECK(canvas.GetPixel(200, 50).g >= 25);
  CHECK(canvas.GetPixel(200, 50).g <= 26);
}

TEST_CASE("DrawShadedTriangle: the middle of a side has the mean of its ends' h", "[shaded]") {
  const Canvas canvas = Shaded(kShaded0, kShaded1, kShaded2);
  // Side P0-P2 at y = 0 is its midpoint: x = -90, h = (0.3 + 1.0) / 2 = 0.65.
  CHECK(canvas.GetPixel(-90, 0).g == cgfs::ToChannel(255 * 0.65));
  // Side P0-P1 at y = -100: x = 0, h = (0.3 + 0.1) / 2 = 0.2; it is the row's right end.
  CHECK(canvas.GetPixel(0, -100).g == cgfs::ToChannel(255 * 0.2));
  // Side P1-P2 at y = 150: x = 110, h = (0.1 + 1.0) / 2 = 0.55.
  CHECK(canvas.GetPixel(110, 150).g == cgfs::ToChannel(255 * 0.55));
}

TEST_CASE("DrawShadedTriangle: h = 1 everywhere is DrawFilledTriangle", "[shaded]") {
  Canvas filled(600, 600);
  DrawFilledTriangle({-200, -250}, {200, 50}, {20, 250}, cgfs::kGreen, filled);
  CHECK(Shaded({-200, -250, 1}, {200, 50, 1}, {20, 250, 1}).GetImage() == filled.GetImage());
}

TEST_CASE("DrawShadedTriangle: the intensity travels with its vertex", "[shaded]") {
  const cgfs::Image expected = Shaded(kShaded0, kShaded1, kShaded2).GetImage();
  CHECK(Shaded(kShaded2, kShaded1, kShaded0).GetImage() == expected);
  CHECK(Shaded(kShaded1, kShaded0, kShaded2).GetImage() == expected);
  CHECK(Shaded(kShaded2, kShaded0, kShaded1).GetImage() == expected);
}

TEST_CASE("DrawShadedTriangle: degenerate triangles draw without crashing", "[shaded]") {
  CHECK(ShadedPixels({-5, 3, 0.5}, {5, 3, 0.5}, {0, 3, 0.5}).size() == 11);
  CHECK(ShadedPixels({0, 0, 1}, {0, 0, 1}, {10, 20, 1}).size() == 21);
  CHECK(ShadedPixels({4, 4, 1}, {4, 4, 1}, {4, 4, 1}) == Pixels{{4, 4}});
  CHECK(ShadedPixels({0, 0, 1}, {5, 10, 1}, {10, 20, 1}).size() == 21);
}

TEST_CASE("ViewportToCanvas scales viewport units to pixels, truncating", "[projection]") {
  const Canvas canvas(600, 600);
  CHECK(ViewportToCanvas(0.5, -0.25, canvas, Viewport{}) == Point{300, -150});
  // -0.5 and 0.5 pixels both truncate toward zero.
  CHECK(ViewportToCanvas(-1.0 / 1200, 1.0 / 1200, canvas, Viewport{}) == Point{0, 0});
  // A wider viewport shows more of the plane, so the same point lands nearer the centre.
  CHECK(ViewportToCanvas(0.5, 0.5, canvas, Viewport{2, 2, 1}) == Point{150, 150});
}

TEST_CASE("ProjectVertex: the corners of the demo cube", "[projection]") {
  const Canvas canvas(600, 600);
  CHECK(ProjectVertex({-2, -0.5, 5}, canvas, Viewport{}) == Point{-240, -60});
  CHECK(ProjectVertex({-1, 0.5, 6}, canvas, Viewport{}) == Point{-100, 50});
  CHECK(ProjectVertex({-2, 0.5, 6}, canvas, Viewport{}) == Point{-200, 50});
  CHECK(ProjectVertex({-1, -0.5, 5}, canvas, Viewport{}) == Point{-120, -60});
}

TEST_CASE("ProjectVertex: the book's cube lands off the canvas", "[projection]") {
  const Canvas canvas(600, 600);
  CHECK(ProjectVertex({-1, 1, 1}, canvas, Viewport{}) == Point{-600, 600});
  CHECK(ProjectVertex({1, -1, 2}, canvas, Viewport{}) == Point{300, -300});
}

TEST_CASE("ProjectVertex: farther is smaller; the distance d scales the picture", "[projection]") {
  const Canvas canvas(600, 600);
  CHECK(ProjectVertex({1, 1, 5}, canvas, Viewport{}).x == 120);
  CHECK(ProjectVertex({1, 1, 10}, canvas, Viewport{}).x == 60);
  CHECK(ProjectVertex({1, 1, 10}, canvas, Viewport{1, 1, 2}).x == 120);
}

namespace {

glm::dvec4 Point4(const Vec3& v) {
  return {v, 1.0};
}

void CheckNear(const Vec3& actual, const Vec3& expected) {
  CHECK(actual.x == Approx(expected.x).margin(1e-6));
  CHECK(actual.y == Approx(expected.y).margin(1e-6));
  CHECK(actual.z == Approx(expected.z).margin(1e-6));
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

TEST_CASE("rotating then translating is not translating then rotating", "[transform]") {
  const glm::dmat4 R = cgfs::MakeOYRotationMatrix(90);
  const glm::dmat4 T = cgfs::MakeTranslationMatrix({0, 0, 5});
  CheckNear(cgfs::ToCartesian(T * R * Point4({0, 0, 1})), {-1, 0, 5});  // Figure 10-4
  CheckNear(cgfs::ToCartesian(R * T * Point4({0, 0, 1})), {-6, 0, 0});  // Figure 10-5
}

TEST_CASE("the camera matrix of figure 10-10, by its action on vectors", "[transform]") {
  const glm::dmat4 M = MakeCameraMatrix({-3, 1, 2}, cgfs::MakeOYRotationMatrix(-30));
  // Rows of the spec: [[0.866025, 0, -0.5, 3.598076], [0, 1, 0, -1],
  //                    [0.5, 0, 0.866025, -0.232051], [0, 0, 0, 1]]; its columns are
  // what it does to the axes and to the origin.
  CheckNear(Vec3(M * glm::dvec4(1, 0, 0, 0)), {0.866025, 0, 0.5});
  CheckNear(Vec3(M * glm::dvec4(0, 1, 0, 0)), {0, 1, 0});
  CheckNear(Vec3(M * glm::dvec4(0, 0, 1, 0)), {-0.5, 0, 0.866025});
  CheckNear(Vec3(M * glm::dvec4(0, 0, 0, 1)), {3.598076, -1, -0.232051});
  CHECK((M * glm::dvec4(0, 0, 0, 1)).w == 1);
  // The camera's own position lands on the origin of camera space.
  CheckNear(cgfs::ToCartesian(M * Point4({-3, 1, 2})), {0, 0, 0});
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
  // The spec prints x = -0.926422; worked out again, 0.866025 * 2.25 - 0.5 * 5.75 = -0.926443.
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

TEST_CASE("the model matrix scales, then rotates, then translates", "[transform]") {
  // The example of "Model Transform": scale 1.5, 45 degrees about Y, then move by (1, 2, 3).
  const Transform transform{1.5, cgfs::MakeOYRotationMatrix(45), {1, 2, 3}};
  CheckNear(cgfs::ToCartesian(MakeTransformMatrix(transform) * Point4({1, 0, 0})),
            {1 + 1.5 * std::sqrt(0.5), 2, 3 + 1.5 * std::sqrt(0.5)});
}

namespace {

const Plane kNear{{0, 0, 1}, -1};

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

TEST_CASE("the five planes of the clipping volume have unit normals", "[clipping]") {
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

TEST_CASE("SignedDistance: positive inside, negative outside", "[clipping]") {
  const Plane left = PlaneNamed(1);
  CHECK(SignedDistance(left, {0, 0, 5}) == Approx(3.535534));
  CHECK(SignedDistance(left, {-3, 0, 2}) == Approx(-0.707107));
  CHECK(SignedDistance(kNear, {0, 0, 1}) == 0);    // on the plane
  CHECK(SignedDistance(kNear, {5, 5, 3}) == 2);    // sideways does not matter to the near plane
  CHECK(SignedDistance(kNear, {0, 0, -4}) == -5);  // behind the camera
}

TEST_CASE("Intersection of a segment with the near plane", "[clipping]") {
  const Vec3 A(0, 0, 0.5);
  const Vec3 B(0, 0, 3);
  CHECK(IntersectionT(A, B, kNear) == Approx(0.2));
  CheckNear(Intersection(A, B, kNear), {0, 0, 1});
  // Any attribute goes along with the same t: 10 at A and 20 at B give 12 at Q.
  CHECK(glm::mix(10.0, 20.0, IntersectionT(A, B, kNear)) == Approx(12));
  // The same crossing, found from the other end.
  CHECK(IntersectionT(B, A, kNear) == Approx(0.8));
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

TEST_CASE("the bounding sphere of the cube: centre 0, radius sqrt 3", "[clipping]") {
  const BoundingSphere sphere = ComputeBoundingSphere(CubeModel().vertices);
  CheckNear(sphere.center, {0, 0, 0});
  CHECK(sphere.radius == Approx(std::sqrt(3.0)));
}

TEST_CASE("instance A of figure 10-10 is accepted whole", "[clipping]") {
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

TEST_CASE("the cube behind the camera is rejected whole", "[clipping]") {
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
  std::vector<CameraSpaceInstance> instances;
  for (const Instance& I : scene.instances) {
    instances.push_back(TransformToCameraSpace(I, M_camera * MakeTransformMatrix(I.transform)));
  }
  CHECK(ClipScene(instances, ClippingPlanes(1)).size() == 2);
}

TEST_CASE("a cube across the near plane is clipped: every vertex ends up at z >= d", "[clipping]") {
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
