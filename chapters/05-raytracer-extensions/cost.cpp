#include "cost.h"

#include "parallel.h"

std::vector<cgfs::Count> CountedPerPixel(const cgfs::Counter& counter, const Canvas& canvas,
                                         const std::function<void()>& draw) {
  const cgfs::Tallying tallying(counter, canvas.Width(), canvas.Height());
  draw();
  return tallying.PerPixel();
}

// The hierarchy counts its own work (kBoxTests, kObjectTests); the loop over every
// object tests each one, always.
TestsPerPixel PrimaryRayTests(const Scene& scene, const Canvas& canvas,
                              const Optimizations& optimizations) {
  Scene prepared = scene;
  PrepareScene(prepared, optimizations);
  const std::size_t pixels =
      static_cast<std::size_t>(canvas.Width()) * static_cast<std::size_t>(canvas.Height());
  if (prepared.bvh == nullptr) {
    return {std::vector<cgfs::Count>(pixels, 0),
            std::vector<cgfs::Count>(pixels, static_cast<cgfs::Count>(prepared.objects.size()))};
  }
  const auto search = [&] {
    ForEachPixel(canvas, optimizations.threads, [&](int x, int y) {
      const Vec3 D = CameraRayDirection(x, y, canvas, prepared);
      ClosestIntersection(prepared.camera.position, D, 1, cgfs::kInf, prepared);
    });
  };
  return {CountedPerPixel(kBoxTests, canvas, search),
          CountedPerPixel(kObjectTests, canvas, search)};
}

std::vector<cgfs::Count> TracedRays(const Scene& scene, int recursion_depth, const Canvas& canvas,
                                    const Optimizations& optimizations) {
  Canvas drawn(canvas.Width(), canvas.Height());
  return CountedPerPixel(kTracedRays, canvas,
                         [&] { RenderScene(scene, recursion_depth, drawn, optimizations); });
}
