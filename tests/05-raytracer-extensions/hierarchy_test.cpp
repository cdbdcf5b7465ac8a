// The bounding-volume hierarchy against a search that shares nothing with it: a
// uniform grid, built here, whose cells list the objects near them. Both must find
// the same object at the same t for every ray, since both end in the objects' own
// Intersect, and so the hierarchy can be checked on far more rays than the loop over
// every object allows.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "bvh.h"
#include "meshes.h"
#include "scenes.h"

namespace {

// The scene prepared twice: with no optimisation, and with the hierarchy alone.
std::pair<Scene, Scene> WithoutAndWithBvh(const Scene& scene) {
  Scene plain = scene;
  PrepareScene(plain, {});
  Optimizations bvh;
  bvh.bvh = true;
  Scene with_bvh = scene;
  PrepareScene(with_bvh, bvh);
  return {plain, with_bvh};
}

// Rays that graze an object: through a point at distance r(1 - u) of a sphere's centre,
// u in [0, 1e-3), or on a triangle's edge or corner, from a random side. A hierarchy
// whose boxes are a hair too small, or that prunes a node a hair too early, misses
// some of them; random rays almost never come so close.
struct GrazingRay {
  Vec3 O;
  Vec3 D;
};

Vec3 RandomUnit(Random& random) {
  const Vec3 v{random.Between(-1, 1), random.Between(-1, 1), random.Between(-1, 1)};
  return glm::length(v) > 1e-3 ? v / glm::length(v) : Vec3{0, 0, 1};
}

GrazingRay Grazing(const Object& object, Random& random) {
  const Vec3 D = RandomUnit(random);
  Vec3 target;
  if (const auto* sphere = dynamic_cast<const Sphere*>(&object)) {
    // A point at the wanted distance from the centre, perpendicular to D.
    Vec3 side = glm::cross(D, RandomUnit(random));
    side /= glm::length(side);
    target = sphere->center + side * (sphere->radius * (1 - 1e-3 * random.Next()));
  } else if (const auto* triangle = dynamic_cast<const Triangle*>(&object)) {
    const double w = random.Next();
    target = random.Next() < 0.5 ? triangle->A * w + triangle->B * (1 - w) : triangle->C;
  } else {
    const Box box = object.Bounds();
    target = box.min + (box.max - box.min) * random.Next();
  }
  return {target - D * (2 + 10 * random.Next()), D};
}

}  // namespace

// The torus, whose 102 400 triangles make the loop slow, is checked against the grid
// below, on many more rays than the loop could afford.
TEST_CASE("Bvh: grazing rays hit what the loop over every object hits", "[optimizations]") {
  for (const Scene& each : {SceneSphereField(1000), SceneCsgNested()}) {
    const int rays = 20000;
    const auto [scene, with_bvh] = WithoutAndWithBvh(each);
    Random random(3);
    cgfs::Count hits = 0;
    for (int i = 0; i < rays; ++i) {
      const Object& object = *scene.objects[static_cast<std::size_t>(
          random.Next() * static_cast<double>(scene.objects.size()))];
      const auto [O, D] = Grazing(object, random);
      const Hit plain = ClosestIntersection(O, D, 0, cgfs::kInf, scene);
      const Hit fast = ClosestIntersection(O, D, 0, cgfs::kInf, with_bvh);
      INFO("ray " << i << " from (" << O.x << ", " << O.y << ", " << O.z << ")");
      REQUIRE(plain.object == fast.object);
      REQUIRE(plain.t == fast.t);
      hits += plain.object >= 0;
    }
    CHECK(hits > rays / 4);  // they do hit: most graze what they aim at, or pass by in front
  }
}

TEST_CASE("Bvh finds what the loop over every object finds", "[optimizations]") {
  // Random rays through the sphere field and the nested solid, from the camera and from
  // points among the objects: the same object, the same t, the same yes or no.
  for (const Scene& each : {SceneSphereField(1000), SceneCsgNested()}) {
    const int rays = 3000;
    const auto [scene, with_bvh] = WithoutAndWithBvh(each);
    Random random(11);
    for (int i = 0; i < rays; ++i) {
      const Vec3 O =
          i % 2 == 0 ? Vec3{0, 0, 0}
                     : Vec3{random.Between(-3, 3), random.Between(-1, 2), random.Between(4, 10)};
      const Vec3 D{random.Between(-1, 1), random.Between(-1, 1), random.Between(-0.5, 1)};
      const double t_max = i % 3 == 0 ? 1.0 : cgfs::kInf;
      const Hit plain = ClosestIntersection(O, D, 0.001, t_max, scene);
      const Hit fast = ClosestIntersection(O, D, 0.001, t_max, with_bvh);
      REQUIRE(plain.object == fast.object);
      REQUIRE(plain.t == fast.t);
      int plain_object = -1;
      int fast_object = -1;
      REQUIRE(AnyIntersection(O, D, 0.001, t_max, scene, plain_object) ==
              AnyIntersection(O, D, 0.001, t_max, with_bvh, fast_object));
      REQUIRE((plain_object >= 0) == (plain.object >= 0));
    }
  }
}

namespace {

// The grid: res³ cells over the box of the objects (but for any object larger than a
// tenth of that box, such as the ground, which every ray tests). Each object is listed
// in every cell its box touches and in their neighbours, one cell further each way, so
// that looking only at the cells of points sampled every half cell along a ray, whose
// own cells are at most one cell away from any cell the ray crosses, finds it.
class GridSearch {
 public:
  explicit GridSearch(const std::vector<std::shared_ptr<Object>>& objects) : objects_(objects) {
    Box all;
    for (const auto& object : objects) {
      all = Union(all, object->Bounds());
    }
    Box small;
    std::vector<int> small_ones;
    for (int i = 0; i < static_cast<int>(objects.size()); ++i) {
      const Box box = objects[i]->Bounds();
      const Vec3 size = box.max - box.min;
      const Vec3 world = all.max - all.min;
      if (size.x > world.x / 10 || size.y > world.y / 10 || size.z > world.z / 10) {
        always_.push_back(i);
      } else {
        small = Union(small, box);
        small_ones.push_back(i);
      }
    }
    res_ = std::clamp(static_cast<int>(2 * std::cbrt(small_ones.size())), 1, 96);
    min_ = small.min;
    cell_ = (small.max - small.min) / static_cast<double>(res_);
    cell_ = glm::max(cell_, Vec3(1e-9));
    cells_.resize(static_cast<std::size_t>(res_) * res_ * res_);
    for (const int i : small_ones) {
      const Box box = objects[i]->Bounds();
      const glm::ivec3 lo = glm::max(CellOf(box.min) - 1, glm::ivec3(0));
      const glm::ivec3 hi = glm::min(CellOf(box.max) + 1, glm::ivec3(res_ - 1));
      for (int x = lo.x; x <= hi.x; ++x) {
        for (int y = lo.y; y <= hi.y; ++y) {
          for (int z = lo.z; z <= hi.z; ++z) {
            cells_[Index({x, y, z})].push_back(i);
          }
        }
      }
    }
    tested_.assign(objects.size(), -1);
  }

  // The closest hit in [t_min, t_max], on a tie the object listed first: what the
  // loop over every object in ClosestIntersection finds.
  Hit Closest(const Vec3& O, const Vec3& D, double t_min, double t_max) {
    ++ray_;
    const Ray ray(O, D);
    Hit best;
    const auto test = [&](int i) {
      if (tested_[i] == ray_) {
        return;
      }
      tested_[i] = ray_;
      Hit hit = objects_[i]->Intersect(ray, t_min, t_max);
      if (hit.t < best.t || (hit.t == best.t && hit.t < cgfs::kInf && i < best.object)) {
        hit.object = i;
        best = hit;
      }
    };
    for (const int i : always_) {
      test(i);
    }
    // The part of the ray inside the grid, widened by a cell, sampled every half cell.
    double enter = t_min;
    double leave = t_max;
    for (int axis = 0; axis < 3; ++axis) {
      const double lo = min_[axis] - cell_[axis];
      const double hi = min_[axis] + (res_ + 1) * cell_[axis];
      if (D[axis] == 0) {
        if (O[axis] < lo || O[axis] > hi) {
          return best;
        }
        continue;
      }
      const double t0 = (lo - O[axis]) / D[axis];
      const double t1 = (hi - O[axis]) / D[axis];
      enter = std::max(enter, std::min(t0, t1));
      leave = std::min(leave, std::max(t0, t1));
    }
    if (!(enter <= leave)) {
      return best;
    }
    double step = cgfs::kInf;
    for (int axis = 0; axis < 3; ++axis) {
      if (D[axis] != 0) {
        step = std::min(step, 0.5 * cell_[axis] / std::abs(D[axis]));
      }
    }
    cgfs::Count last = -1;
    for (double t = enter;; t = std::min(t + step, leave)) {
      const glm::ivec3 cell = glm::clamp(CellOf(O + t * D), glm::ivec3(0), glm::ivec3(res_ - 1));
      const cgfs::Count index = static_cast<cgfs::Count>(Index(cell));
      if (index != last) {
        for (const int i : cells_[index]) {
          test(i);
        }
        last = index;
      }
      // Every object hit at or before t has been tested by now (the samples are half a
      // cell apart, and each object is listed in the cells around its box), so nothing
      // left along the ray can be nearer than a hit found at or before t.
      if (t >= leave || t >= best.t) {
        break;
      }
    }
    return best;
  }

 private:
  glm::ivec3 CellOf(const Vec3& P) const {
    const Vec3 c = glm::floor((P - min_) / cell_);
    return glm::ivec3(glm::clamp(c, Vec3(-2), Vec3(res_ + 1)));
  }
  std::size_t Index(const glm::ivec3& c) const {
    return (static_cast<std::size_t>(c.x) * res_ + c.y) * res_ + c.z;
  }

  const std::vector<std::shared_ptr<Object>>& objects_;
  std::vector<int> always_;
  int res_ = 1;
  Vec3 min_{0, 0, 0};
  Vec3 cell_{1, 1, 1};
  std::vector<std::vector<int>> cells_;
  std::vector<cgfs::Count> tested_;  // the last ray that tested each object
  cgfs::Count ray_ = 0;
};

// A ray as the checks below draw them.
struct TestRay {
  Vec3 O;
  Vec3 D;
  double t_min;
  double t_max;
};

// Four kinds, in turn: from the camera through a random point of the objects' region;
// between two random points among the objects (a shadow ray's segment, t in [0.001,
// 1]); grazing an object's silhouette (a sphere at r(1 - u), u < 1e-3; a triangle's
// edge or corner); and through an edge or a corner of an object's box, where the
// hierarchy's boxes have their faces.
TestRay Draw(int kind, const Scene& scene, const Box& region, Random& random) {
  const auto inside = [&] {
    return region.min +
           (region.max - region.min) * Vec3{random.Next(), random.Next(), random.Next()};
  };
  const auto object = [&]() -> const Object& {
    return *scene.objects[static_cast<std::size_t>(random.Next() *
                                                   static_cast<double>(scene.objects.size()))];
  };
  const Vec3 D = RandomUnit(random);
  switch (kind) {
    case 0:
      return {scene.camera.position, inside() - scene.camera.position, 1, cgfs::kInf};
    case 1: {
      const Vec3 from = inside();
      return {from, inside() - from, 0.001, 1};
    }
    case 2: {
      const auto [O, direction] = Grazing(object(), random);
      return {O, direction, 0, cgfs::kInf};
    }
    default: {
      // A corner of the box, or a point on one of its edges: two coordinates from the
      // corners, the third anywhere between them.
      const Box box = object().Bounds();
      Vec3 point;
      const int free_axis = static_cast<int>(random.Next() * 4);  // 3: a corner
      for (int axis = 0; axis < 3; ++axis) {
        const double w = axis == free_axis ? random.Next() : (random.Next() < 0.5 ? 0 : 1);
        point[axis] = box.min[axis] + (box.max[axis] - box.min[axis]) * w;
      }
      return {point - D * (1 + 5 * random.Next()), D, 0, cgfs::kInf};
    }
  }
}

// The objects' region: the box of all but the ground.
Box Region(const Scene& scene) {
  Box region;
  for (const auto& object : scene.objects) {
    const Box box = object->Bounds();
    if (box.max.x - box.min.x < 100) {
      region = Union(region, box);
    }
  }
  return region;
}

// The reference must be right before it judges: on the scenes it judges, where the
// plain loop is still quick, grid and loop agree on every ray.
void CheckGridAgainstLoop(Scene scene, int rays) {
  PrepareScene(scene, {});
  GridSearch grid(scene.objects);
  const Box region = Region(scene);
  Random random(9);
  for (int i = 0; i < rays; ++i) {
    const TestRay ray = Draw(i % 4, scene, region, random);
    const Hit loop = ClosestIntersection(ray.O, ray.D, ray.t_min, ray.t_max, scene);
    const Hit cells = grid.Closest(ray.O, ray.D, ray.t_min, ray.t_max);
    REQUIRE(cells.object == loop.object);
    REQUIRE(cells.t == loop.t);
  }
}

// `rays` rays of the four kinds through the scene: the hierarchy's closest hit, and
// its any-hit answer, against the grid's.
void CheckAgainstGrid(const std::string& name, const Scene& original, cgfs::Count rays) {
  Scene scene = original;
  Optimizations bvh;
  bvh.bvh = true;
  bvh.cache = true;
  PrepareScene(scene, bvh);
  GridSearch grid(scene.objects);
  const Box region = Region(scene);
  Random random(2026);
  cgfs::Count hits[4] = {};
  cgfs::Count misses = 0;
  for (cgfs::Count i = 0; i < rays; ++i) {
    const int kind = static_cast<int>(i % 4);
    const TestRay ray = Draw(kind, scene, region, random);
    const Hit expected = grid.Closest(ray.O, ray.D, ray.t_min, ray.t_max);
    const Hit found = ClosestIntersection(ray.O, ray.D, ray.t_min, ray.t_max, scene);
    int any = -1;
    const bool blocked = AnyIntersection(ray.O, ray.D, ray.t_min, ray.t_max, scene, any);
    if (found.object != expected.object || found.t != expected.t ||
        blocked != (expected.object >= 0)) {
      INFO(name << ", ray " << i << " of kind " << kind << ": expected object " << expected.object
                << " at t = " << expected.t << ", found " << found.object << " at t = " << found.t
                << ", any-hit " << blocked);
      REQUIRE(false);
    }
    hits[kind] += expected.object >= 0;
    misses += expected.object < 0;
  }
  // Each kind hits something often enough to mean something, and some rays miss.
  INFO(name << ": hits of each kind " << hits[0] << ", " << hits[1] << ", " << hits[2] << ", "
            << hits[3] << " of " << rays / 4 << "; " << misses << " misses");
  for (const cgfs::Count kind_hits : hits) {
    CHECK(kind_hits > rays / 40);
  }
  CHECK(misses > rays / 40);
}

}  // namespace

TEST_CASE("GridSearch finds what the loop over every object finds", "[optimizations]") {
  CheckGridAgainstLoop(SceneSphereField(1000), 4000);
  CheckGridAgainstLoop(SceneTorusMesh(), 400);
  CheckGridAgainstLoop(SceneCsgNested(), 400);
}

TEST_CASE("Bvh finds what the grid finds: 10 000 rays of four kinds per scene", "[optimizations]") {
  CheckAgainstGrid("sphere-field-1000", SceneSphereField(1000), 10000);
  CheckAgainstGrid("torus-mesh", SceneTorusMesh(), 10000);
  CheckAgainstGrid("csg-nested", SceneCsgNested(), 10000);
}

// A million rays per scene: a minute, so not part of the test command (its grid first
// checked on more rays than there); run it with
// build/tests/05-raytracer-extensions-tests "[million]".
TEST_CASE("Bvh finds what the grid finds: a million rays of four kinds per scene", "[.][million]") {
  CheckGridAgainstLoop(SceneTorusMesh(), 4000);
  CheckGridAgainstLoop(SceneCsgNested(), 4000);
  CheckAgainstGrid("sphere-field-1000", SceneSphereField(1000), 1000000);
  CheckAgainstGrid("sphere-field-100000", SceneSphereField(100000), 1000000);
  CheckAgainstGrid("torus-mesh", SceneTorusMesh(), 1000000);
  CheckAgainstGrid("csg-nested", SceneCsgNested(), 1000000);
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

TEST_CASE("Bvh: a node entered just before the best hit so far is still visited", "[equations]") {
  // A big sphere, split off from the small ones: the ray down the z axis enters its
  // box first (z = 15), and the walk takes it first (its side of the split along x, since
  // the ray runs parallel to that axis), and hits it at z = 16; the small sphere on the
  // axis, in the other subtree, is hit at z = 15.9995: nearer, though its node is
  // entered only 0.003 % before 16.
  std::vector<std::shared_ptr<Object>> objects;
  objects.push_back(std::make_shared<Sphere>(Vec3{-3, 0, 20}, 5, cgfs::kRed));
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
