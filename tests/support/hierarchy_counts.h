// The work of chapter 5's and chapter 17's hierarchies, counted: the box and object tests
// Bvh::Closest makes for the camera's rays through a 60 x 60 grid of a 600x600 canvas, on
// average per ray (counted through the tally, cgfs/tally.h). Included by the chapter's
// tests, so that `Scene`, `Bvh` and the rest are the chapter's own.
#pragma once

#include "cgfs/tally.h"
#include "scenes.h"

namespace cgfs::test {

struct TestsPerRay {
  double boxes = 0;
  double objects = 0;
};

inline TestsPerRay TestsPerPrimaryRay(Scene scene) {
  Optimizations bvh;
  bvh.bvh = true;
  PrepareScene(scene, bvh);
  const Canvas canvas(600, 600);
  int rays = 0;
  const auto search = [&] {
    rays = 0;
    for (int x = -300; x < 300; x += 10) {
      for (int y = -300; y < 300; y += 10) {
        const Vec3 D = CameraRayDirection(x, y, canvas, scene);
        int object = -1;
        scene.bvh->Closest(MakeRay(scene.camera.position, D, scene), 1, cgfs::kInf, object);
        ++rays;
      }
    }
  };
  const auto total = [&](const cgfs::Counter& counter) {
    const cgfs::Tallying tallying(counter, 0, 0);  // no pixels: the total only
    search();
    return static_cast<double>(tallying.Total()) / rays;
  };
  return {total(kBoxTests), total(kObjectTests)};
}

}  // namespace cgfs::test
