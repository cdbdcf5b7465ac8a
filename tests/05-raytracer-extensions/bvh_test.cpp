// The bounding-volume hierarchy's work, counted: how many boxes and objects a ray tests.
#include <catch2/catch.hpp>

#include "bvh.h"
#include "scenes.h"

TEST_CASE("Bvh: a primary ray through 10 000 spheres makes a few dozen tests, not thousands",
          "[equations]") {
  // The camera's rays through a 60 x 60 grid of the canvas, over the 10 000-sphere
  // field and its ground: the tests Closest makes per ray, counted (a box per node
  // visited). Bounds 6 % above what the surface-area tree makes (30.9 box tests and 5.84
  // sphere tests per ray): halving splits at the median centre (42.2 box tests, 7.65
  // sphere tests) break both.
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
      int object = -1;
      scene.bvh->Closest(MakeRay(scene.camera.position, D, scene), 1, cgfs::kInf, object, &total);
      ++rays;
    }
  }
  const double boxes = static_cast<double>(total.boxes) / rays;
  const double objects = static_cast<double>(total.objects) / rays;
  INFO("per ray: " << boxes << " box tests, " << objects << " object tests");
  CHECK(boxes < 32.8);
  CHECK(objects < 6.2);
}
