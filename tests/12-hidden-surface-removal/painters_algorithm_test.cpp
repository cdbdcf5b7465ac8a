// "Painter's Algorithm": the sort key, the stable back-to-front order, and the
// cases where no order of whole triangles is right.
#include <catch2/catch.hpp>

#include <cmath>

#include "golden.h"
#include "painters_algorithm.h"
#include "pixels.h"
#include "printing.h"
#include "scenes.h"

using Catch::Detail::Approx;
using cgfs::Rgb8;
using cgfs::test::ChangedPixels;
using cgfs::test::RenderFigureNamed;

namespace {

SceneTriangle At(double z0, double z1, double z2, const Color& color) {
  return {{Vec3(0, 0, z0), Vec3(1, 0, z1), Vec3(0, 1, z2)}, color};
}

}  // namespace

TEST_CASE("PaintersDepth: the camera-space z of the centroid", "[painter]") {
  CHECK(PaintersDepth(At(3, 6, 9, cgfs::kRed)) == Approx(6));
  CHECK(PaintersDepth(At(4, 4, 6, cgfs::kRed)) == Approx(14.0 / 3));
}

TEST_CASE("SortBackToFront: farthest first, ties in their original order", "[painter]") {
  std::vector<SceneTriangle> triangles = {At(5, 5, 5, cgfs::kRed), At(9, 9, 9, cgfs::kGreen),
                                          At(4, 5, 6, cgfs::kBlue), At(2, 2, 2, cgfs::kYellow),
                                          At(6, 5, 4, cgfs::kCyan)};
  SortBackToFront(triangles);
  std::vector<Color> order;
  for (const SceneTriangle& T : triangles) {
    order.push_back(T.color);
  }
  // Red, blue and cyan all have depth 5: they stay red, blue, cyan.
  CHECK(order ==
        std::vector<Color>{cgfs::kGreen, cgfs::kRed, cgfs::kBlue, cgfs::kCyan, cgfs::kYellow});
}

TEST_CASE("CollectTriangles: every triangle of every instance, in camera space", "[painter]") {
  CameraSpaceScene scene;
  scene.instances.push_back({{{{0, 0, 5}, {1, 0, 5}, {0, 1, 5}}, {{{0, 1, 2}, cgfs::kRed}}}, {}});
  scene.instances.push_back({{{{0, 0, 7}, {1, 0, 8}, {0, 1, 9}, {2, 2, 9}},
                              {{{0, 1, 2}, cgfs::kGreen}, {{3, 2, 1}, cgfs::kBlue}}},
                             {}});
  const std::vector<SceneTriangle> triangles = CollectTriangles(scene);
  REQUIRE(triangles.size() == 3);
  CHECK(triangles[0].color == cgfs::kRed);
  CHECK(triangles[2].color == cgfs::kBlue);
  CHECK(triangles[2].vertices[0] == Vec3(2, 2, 9));  // in the triangle's own order
  CHECK(triangles[2].vertices[2] == Vec3(1, 0, 8));
}

TEST_CASE("the book's sorting costs are n log10 n: 200, 460 and 2322, not 400 and 1840",
          "[painter]") {
  // "Painter's Algorithm": twice the triangles take more than twice the time.
  const auto cost = [](double n) { return n * std::log10(n); };
  CHECK(cost(100) == Approx(200));
  CHECK(std::round(cost(200)) == 460);
  CHECK(std::round(cost(800)) == 2322);
  CHECK(cost(200) > 2 * cost(100));
}

TEST_CASE("the painter draws squares at different depths as the depth buffer does", "[painter]") {
  const Canvas painter = RenderFigureNamed(Figures(), "painters-algorithm");
  Canvas depth(600, 600);
  RenderScene(SceneOverlappingSquares(), depth, {.cull_back_faces = false});
  CHECK(painter.GetImage() == depth.GetImage());
  // In model order the far squares paint over the near ones.
  const Canvas model_order = RenderFigureNamed(Figures(), "overlapping-squares-model-order");
  CHECK(ChangedPixels(model_order, painter).size() > 1000);
}

TEST_CASE("Figure 12-2's cycle: the painter gets one crossing wrong, the depth buffer none",
          "[painter]") {
  const Canvas painter = RenderFigureNamed(Figures(), "cyclic-overlap-painters");
  const Canvas depth = RenderFigureNamed(Figures(), "cyclic-overlap-depth-buffer");
  CHECK(!ChangedPixels(painter, depth).empty());
  // Near the top, the red triangle's wide end crosses the blue one's tip.
  CHECK(depth.GetPixel(-3, 124) == Rgb8{255, 0, 0});
  CHECK(painter.GetPixel(-3, 124) == Rgb8{0, 0, 255});
}

TEST_CASE("triangles passing through each other: the painter draws one over the other",
          "[painter]") {
  const Canvas painter = RenderFigureNamed(Figures(), "intersecting-painters");
  const Canvas depth = RenderFigureNamed(Figures(), "intersecting-depth-buffer");
  CHECK(!ChangedPixels(painter, depth).empty());
  // Left of where they cross the blue triangle is in front, right of it the red one.
  CHECK(depth.GetPixel(-49, 15) == Rgb8{0, 0, 255});
  CHECK(depth.GetPixel(60, -20) == Rgb8{255, 0, 0});
  CHECK(painter.GetPixel(-49, 15) == Rgb8{255, 0, 0});
  CHECK(painter.GetPixel(60, -20) == Rgb8{255, 0, 0});
}

TEST_CASE("on Figure 10-10's cubes the centroid puts a hidden bottom over a side", "[painter]") {
  const Canvas painter = RenderFigureNamed(Figures(), "painters-algorithm-cubes");
  const Canvas depth = RenderFigureNamed(Figures(), "fig-12-4-depth-buffer");
  CHECK(depth.GetPixel(-230, -215) == Rgb8{255, 255, 0});    // instance A's left face
  CHECK(painter.GetPixel(-230, -215) == Rgb8{0, 255, 255});  // its bottom, over it
}
