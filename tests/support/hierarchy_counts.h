// The work of chapter 5's and chapter 17's hierarchies, counted: the box and object tests
// Bvh::Closest makes for the camera's rays through a 60 x 60 grid of a 600x600 canvas, on
// average per ray. Included by the chapter's tests, so that `Scene`, `Bvh` and the rest
// are the chapter's own.
#pragma once

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
  return {static_cast<double>(total.boxes) / rays, static_cast<double>(total.objects) / rays};
}

}  // namespace cgfs::test
