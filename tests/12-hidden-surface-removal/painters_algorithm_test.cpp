// "Painter's Algorithm": the sort key and the stable back-to-front order; the figures
// are in figures_test.cpp. Chapter 12's alone: from chapter 13 on, the depth buffer
// has taken the painter's place.
#include <catch2/catch.hpp>

#include "painters_algorithm.h"
#include "scenes.h"

using Catch::Detail::Approx;

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
