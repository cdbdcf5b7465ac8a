#include "cost.h"

#include "parallel.h"

// The hierarchy counts its own work (Bvh::Closest's `tests`); the loop over every
// object tests each one, always.
TestsPerPixel PrimaryRayTests(const Scene& scene, const Canvas& canvas,
                              const Optimizations& optimizations) {
  Scene prepared = scene;
  PrepareScene(prepared, optimizations);
  const std::size_t pixels =
      static_cast<std::size_t>(canvas.Width()) * static_cast<std::size_t>(canvas.Height());
  TestsPerPixel counts{std::vector<long>(pixels, 0), std::vector<long>(pixels, 0)};
  ForEachTile(canvas.Width(), canvas.Height(), optimizations.threads, [&](const Tile& tile) {
    for (int x = tile.x_begin; x < tile.x_end; ++x) {
      for (int y = tile.y_begin; y < tile.y_end; ++y) {
        const std::size_t pixel = PixelIndex(x, y, canvas);
        if (prepared.bvh == nullptr) {
          counts.objects[pixel] = static_cast<long>(prepared.objects.size());
          continue;
        }
        const Vec3 D = CameraRayDirection(x, y, canvas, prepared);
        Bvh::Tests tests;
        int object = -1;
        prepared.bvh->Closest(MakeRay(prepared.camera.position, D, prepared), 1, cgfs::kInf, object,
                              &tests);
        counts.boxes[pixel] = tests.boxes;
        counts.objects[pixel] = tests.objects;
      }
    }
  });
  return counts;
}

std::vector<long> TracedRays(const Scene& scene, int recursion_depth, const Canvas& canvas,
                             const Optimizations& optimizations) {
  Scene prepared = scene;
  PrepareScene(prepared, optimizations);
  long traced = 0;
  prepared.traced_rays = &traced;
  std::vector<long> rays(static_cast<std::size_t>(canvas.Width()) * canvas.Height(), 0);
  for (int x = -canvas.Width() / 2; x < canvas.Width() / 2; ++x) {
    for (int y = -canvas.Height() / 2; y < canvas.Height() / 2; ++y) {
      traced = 0;
      const Vec3 D = CameraRayDirection(x, y, canvas, prepared);
      TraceRay(prepared.camera.position, D, 1, cgfs::kInf, recursion_depth, prepared);
      rays[PixelIndex(x, y, canvas)] = traced;
    }
  }
  return rays;
}
