// "Supporting Other Primitives" and "Caching Invariants": triangles, the cached
// sphere intersection, and the boxes of the hierarchy.
#include <catch2/catch.hpp>

#include <cmath>

#include "bvh.h"
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

TEST_CASE("RayHitsBox: the slab test and its entry t", "[equations]") {
  const Box box{{-1, -1, 4}, {1, 1, 6}};
  const Vec3 O{0, 0, 0};
  double t = -1;
  const Vec3 D{0, 0, 1};
  CHECK(RayHitsBox(box, O, D, 1.0 / D, 0, cgfs::kInf, t));
  CHECK(t == 4);
  // Parallel to two pairs of slabs, the ray is inside them or never.
  const Vec3 beside{2, 0, 1};
  CHECK_FALSE(RayHitsBox(box, {2, 0, 0}, D, 1.0 / D, 0, cgfs::kInf, t));
  CHECK(RayHitsBox(box, O, beside, 1.0 / beside, 0, cgfs::kInf, t) == false);
  // The range of t counts: the box lies at t in [4, 6].
  CHECK_FALSE(RayHitsBox(box, O, D, 1.0 / D, 0, 3.9, t));
  CHECK_FALSE(RayHitsBox(box, O, D, 1.0 / D, 6.1, cgfs::kInf, t));
  CHECK(RayHitsBox(box, O, D, 1.0 / D, 5, cgfs::kInf, t));
  CHECK(t == 5);
}

TEST_CASE("Bvh: the surface area heuristic keeps a sphere field's tree cheap", "[equations]") {
  // The expected cost of a ray through the root, in object tests, over the field's 1000
  // spheres: halving splits at the median centre into leaves of 4 (the first builder)
  // cost 62.9, the binned surface area heuristic 55.2. Depth and node count are the
  // builder's business; the cost is what a ray pays.
  Scene scene = SceneSphereField(1000);
  std::vector<std::shared_ptr<Object>> field;  // the ground left out: its box is the world
  for (const auto& object : scene.objects) {
    const Box box = object->Bounds();
    if (box.max.x - box.min.x < 100) {
      field.push_back(object);
    }
  }
  REQUIRE(field.size() == 1000);
  const Bvh bvh(field);
  INFO("cost " << bvh.SurfaceAreaCost() << ", depth " << bvh.Depth());
  CHECK(bvh.SurfaceAreaCost() < 58);
  CHECK(bvh.Depth() < 40);
  CHECK(bvh.NodeCount() < 2 * 1001);
}

TEST_CASE("Bvh: a node entered just before the best hit so far is still visited", "[equations]") {
  // A big sphere, larger than all the others together, gets a leaf of its own beside
  // the tree of the rest. The ray down the z axis enters its box first (z = 15) and
  // hits it at z = 16; the small sphere on the axis, in the other subtree, is hit at
  // z = 15.9995: nearer, though its node is entered only 0.003 % before 16.
  std::vector<std::shared_ptr<Object>> objects;
  objects.push_back(std::make_shared<Sphere>(Vec3{3, 0, 20}, 5, cgfs::kRed));
  objects.push_back(std::make_shared<Sphere>(Vec3{0, 0, 16.0095}, 0.01, cgfs::kGreen));
  for (int i = 0; i < 6; ++i) {  // off the ray's way, behind
    objects.push_back(std::make_shared<Sphere>(Vec3{0.5 + 0.1 * i, 1, 17}, 0.01, cgfs::kBlue));
  }
  const Bvh bvh(objects);
  REQUIRE(bvh.NodeCount() > 1);
  int object = -1;
  const Hit hit = bvh.Closest(Ray{{0, 0, 0}, {0, 0, 1}}, 1, cgfs::kInf, object);
  CHECK(object == 1);
  CHECK(hit.t == Approx(15.9995).epsilon(1e-12));
}

TEST_CASE("Bvh: a primary ray through 10 000 spheres makes a few dozen tests, not thousands",
          "[equations]") {
  // The camera's rays through a 60 x 60 grid of the canvas, over the 10 000-sphere
  // field and its ground: the tests Closest makes per ray, counted. Bounds 6 % above
  // what the surface-area tree makes (28.9 box tests and 5.82 sphere tests per ray):
  // halving splits at the median (32.9 box tests, 6.28 sphere tests) or leaves twice
  // as large (11.9 sphere tests) break them.
  Scene scene = SceneSphereField(10000);
  Optimizations bvh;
  bvh.bvh = true;
  PrepareScene(scene, bvh);
  const Canvas canvas(600, 600);
  Bvh::Tests total;
  int rays = 0;
  for (int x = -300; x < 300; x += 10) {
    for (int y = -300; y < 300; y += 10) {
      const Vec3 D = CameraRayDirection(x, y, canvas, scene);
      const Bvh::Tests tests =
          scene.bvh->CountClosest(MakeRay(scene.camera.position, D, scene), 1, cgfs::kInf);
      total.boxes += tests.boxes;
      total.objects += tests.objects;
      ++rays;
    }
  }
  const double boxes = static_cast<double>(total.boxes) / rays;
  const double objects = static_cast<double>(total.objects) / rays;
  INFO("per ray: " << boxes << " box tests, " << objects << " object tests");
  CHECK(boxes < 30.6);
  CHECK(objects < 6.2);
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
