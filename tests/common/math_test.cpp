// The linear algebra appendix, as GLM does it. These pin the conventions (double
// precision, column vectors, matCxR storage) that the chapters rely on.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/mat3x2.hpp>
#include <glm/mat4x2.hpp>
#include <glm/mat4x3.hpp>

#include "cgfs/math.h"

using Catch::Detail::Approx;
using cgfs::Vec3;

TEST_CASE("dot, cross, length and normalize", "[math]") {
  CHECK(glm::dot(Vec3(1, 2, 3), Vec3(4, 5, 6)) == 32);
  CHECK(glm::cross(Vec3(1, 0, 0), Vec3(0, 1, 0)) == Vec3(0, 0, 1));
  CHECK(glm::cross(Vec3(0, 1, 0), Vec3(1, 0, 0)) == Vec3(0, 0, -1));
  CHECK(glm::cross(Vec3(2, 3, 4), Vec3(5, 6, 7)) == Vec3(-3, 6, -3));
  CHECK(glm::length(Vec3(3, 4, 12)) == 13);
  const Vec3 n = glm::normalize(Vec3(0, 3, 4));
  CHECK(n.x == 0);
  CHECK(n.y == Approx(0.6));
  CHECK(n.z == Approx(0.8));
}

TEST_CASE("the angle between two vectors comes from the dot product", "[math]") {
  const Vec3 v(1, 0, 0);
  const Vec3 w(1, 1, 0);
  const double angle = std::acos(glm::dot(v, w) / (glm::length(v) * glm::length(w)));
  CHECK(angle * 180 / std::numbers::pi == Approx(45));
}

TEST_CASE("matrix products, with GLM's column-major storage", "[math]") {
  // glm::dmatCxR has C columns and R rows; the constructor takes columns.
  const glm::dmat3x2 a(1, 4, 2, 5, 3, 6);                    // [[1,2,3],[4,5,6]]
  const glm::dmat4x3 b(1, 0, 1, 0, 1, 1, 2, 1, 0, 1, 0, 2);  // [[1,0,2,1],[0,1,1,0],[1,1,0,2]]
  const glm::dmat4x2 product = a * b;
  const double expected[2][4] = {{4, 5, 4, 7}, {10, 11, 13, 16}};
  for (int row = 0; row < 2; ++row) {
    for (int column = 0; column < 4; ++column) {
      CHECK(product[column][row] == expected[row][column]);
    }
  }
  CHECK(a * Vec3(1, 0, -1) == glm::dvec2(-2, -2));
}

TEST_CASE("homogeneous points and vectors", "[math]") {
  CHECK(glm::dvec4(8, 4, 2, 1) - glm::dvec4(3, 2, 1, 1) == glm::dvec4(5, 2, 1, 0));
  CHECK(glm::dvec4(0, 0, 1, 0) + glm::dvec4(1, 0, 0, 0) == glm::dvec4(1, 0, 1, 0));
  CHECK(cgfs::ToCartesian(glm::dvec4(2, 4, 6, 2)) == Vec3(1, 2, 3));
  CHECK(cgfs::ToCartesian(glm::dvec4(-3, -6, -9, -3)) == Vec3(1, 2, 3));
}
