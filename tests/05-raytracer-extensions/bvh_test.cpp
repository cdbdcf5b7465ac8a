// The bounding-volume hierarchy's work, counted: how many boxes and objects a ray tests.
#include <catch2/catch.hpp>

#include "bvh.h"
#include "hierarchy_counts.h"
#include "scenes.h"

TEST_CASE("Bvh: a primary ray through 10 000 spheres makes a few dozen tests, not thousands",
          "[equations]") {
  // The camera's rays through a 60 x 60 grid of the canvas, over the 10 000-sphere
  // field and its ground: the tests Closest makes per ray, counted (a box per node
  // visited). Bounds 6 % above what the surface-area tree makes (30.9 box tests and 5.84
  // sphere tests per ray): halving splits at the median centre (42.2 box tests, 7.65
  // sphere tests) break both.
  const cgfs::test::TestsPerRay per_ray = cgfs::test::TestsPerPrimaryRay(SceneSphereField(10000));
  INFO("per ray: " << per_ray.boxes << " box tests, " << per_ray.objects << " object tests");
  CHECK(per_ray.boxes < 32.8);
  CHECK(per_ray.objects < 6.2);
}
