// "Supporting Other Primitives" and "Caching Invariants": triangles, the cached
// sphere intersection, and the sphere fields.
#include <catch2/catch.hpp>

#include <cmath>

#include "meshes.h"
#include "printing.h"
#include "raytracer.h"
#include "scenes.h"

namespace {

const Triangle kTriangle{{0, 0, 5}, {1, 0, 5}, {0, 1, 5}, cgfs::kRed};

}  // namespace

TEST_CASE("IntersectRayTriangle: the plane's t when the point is inside", "[equations]") {
  // N = (B - A) x (C - A) = (0, 0, 1); the plane is z = 5.
  CHECK(kTriangle.N == Vec3(0, 0, 1));
  CHECK(IntersectRayTriangle({0, 0, 0}, {0.05, 0.05, 1}, kTriangle) == 5);
  CHECK(IntersectRayTriangle({0, 0, 0}, {0.025, 0.025, 0.5}, kTriangle) == 10);
}

TEST_CASE("IntersectRayTriangle: outside the triangle, on its plane, is a miss", "[equations]") {
  // (0.75, 0.75, 5) is past the edge BC (x + y = 1).
  CHECK(IntersectRayTriangle({0, 0, 0}, {0.15, 0.15, 1}, kTriangle) == cgfs::kInf);
  CHECK(IntersectRayTriangle({0, 0, 0}, {-0.01, 0.5, 5}, kTriangle) == cgfs::kInf);
}

TEST_CASE("IntersectRayTriangle: a ray parallel to the plane is rejected", "[equations]") {
  CHECK(IntersectRayTriangle({0, 0, 5}, {1, 0, 0}, kTriangle) == cgfs::kInf);
  CHECK(IntersectRayTriangle({0, 0, 0}, {1, 1, 0}, kTriangle) == cgfs::kInf);
}

TEST_CASE("IntersectRayTriangle: a point on an edge is inside", "[equations]") {
  CHECK(IntersectRayTriangle({0, 0, 0}, {0.1, 0, 1}, kTriangle) == 5);  // on AB at (0.5, 0, 5)
}

TEST_CASE("IntersectRayTriangle: behind the origin, t is negative and Intersect rejects it",
          "[equations]") {
  CHECK(IntersectRayTriangle({0.2, 0.2, 10}, {0, 0, 1}, kTriangle) == -5);
  CHECK(kTriangle.Intersect(Ray{{0.2, 0.2, 10}, {0, 0, 1}}, 1, cgfs::kInf).primitive == nullptr);
}

TEST_CASE("IntersectRaySphere with cached invariants finds the very same roots", "[equations]") {
  // Same arithmetic on the same values: equal to the last bit, for rays from the
  // camera (cached <CO,CO>) and from elsewhere.
  Random random(7);
  const Vec3 camera{0.5, 1, -2};
  for (int i = 0; i < 2000; ++i) {
    const Sphere plain({random.Between(-3, 3), random.Between(-3, 3), random.Between(2, 9)},
                       random.Between(0.1, 2), cgfs::kRed);
    const std::shared_ptr<Object> prepared = plain.Prepared(camera);
    const Sphere& sphere = static_cast<const Sphere&>(*prepared);
    const bool from_camera = i % 2 == 0;
    const Vec3 O = from_camera ? camera : Vec3{random.Between(-1, 1), 0, random.Between(-1, 1)};
    const Vec3 D{random.Between(-1, 1), random.Between(-1, 1), random.Between(0.2, 2)};
    const Ray ray(O, D, from_camera);
    const auto book = IntersectRaySphere(O, D, sphere);
    const auto cached = IntersectRaySphere(ray, sphere.center, sphere.cache);
    REQUIRE(book.first == cached.first);
    REQUIRE(book.second == cached.second);
  }
}

TEST_CASE("SphereField places the same spheres on every machine", "[equations]") {
  // The generator's arithmetic is on integers, and the conversion to double exact: its
  // first numbers for the figures' seed, and where they put the first sphere, are
  // the same bits everywhere.
  Random random(20261122);
  CHECK(random.Next() == 0x1.5a2c4e617684p-4);
  CHECK(random.Next() == 0x1.f9425aeb80efep-1);
  const std::vector<Sphere> field = SphereField(100, 20261122);
  REQUIRE(field.size() == 100);
  CHECK(field[0].radius == 0.3);
  CHECK(field[0].center == Vec3(-0x1.3f17b14db9c74p+1, 0x1.3a4533ae93ff2p+1, 0x1.0ab49051ed3f6p+3));
}
