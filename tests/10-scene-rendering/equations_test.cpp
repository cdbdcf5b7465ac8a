// Spec §7.4 to §10.4: Interpolate, DrawLine, the triangles and the projection, with exact
// outputs.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
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
  CHECK(ProjectVertex({1, 1, 5}, canvas, Viewport{})->x == 120);
  CHECK(ProjectVertex({1, 1, 10}, canvas, Viewport{})->x == 60);
  CHECK(ProjectVertex({1, 1, 10}, canvas, Viewport{1, 1, 2})->x == 120);
}

TEST_CASE("ProjectVertex refuses points in front of the projection plane", "[projection]") {
  const Canvas canvas(600, 600);
  CHECK_FALSE(ProjectVertex({1, 1, 0}, canvas, Viewport{}));   // would divide by zero
  CHECK_FALSE(ProjectVertex({1, 1, -5}, canvas, Viewport{}));  // behind the camera
  CHECK_FALSE(
      ProjectVertex({1, 1, 1e-300}, canvas, Viewport{}));  // would be astronomically far out
  CHECK_FALSE(ProjectVertex({1, 1, 0.999}, canvas, Viewport{}));
  CHECK(ProjectVertex({0.5, 0.5, 1}, canvas, Viewport{}) == Point{300, 300});  // on the plane
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

TEST_CASE("ApplyTransform scales, then rotates, then translates", "[transform]") {
  // The example of "Model Transform": scale 1.5, 45 degrees about Y, then move by (1, 2, 3).
  const Transform transform{1.5, cgfs::MakeOYRotationMatrix(45), {1, 2, 3}};
  const Vec3 moved = ApplyTransform({1, 0, 0}, transform);
  // (1,0,0) -> (1.5,0,0) -> OY(45): (1.5 cos 45, 0, 1.5 sin 45) -> + (1, 2, 3)
  CheckNear(moved, {1 + 1.5 * std::sqrt(0.5), 2, 3 + 1.5 * std::sqrt(0.5)});
  // The matrix of "The Transform Matrix" does the same to every vertex.
  for (const Vec3& V : CubeModel().vertices) {
    CheckNear(cgfs::ToCartesian(MakeTransformMatrix(transform) * Point4(V)),
              ApplyTransform(V, transform));
  }
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
