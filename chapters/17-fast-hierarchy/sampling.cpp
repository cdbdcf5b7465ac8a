#include "sampling.h"

#include <algorithm>
#include <atomic>
#include <vector>

#include "parallel.h"

namespace {

// What one primary ray found: its colour and the scene object it hit (-1: none).
struct Sample {
  Color color;
  int object = -1;
};

Sample TraceCameraRay(double x, double y, int recursion_depth, const Scene& scene,
                      const Canvas& canvas) {
  cgfs::Tally(kCameraRays);
  const Vec3 O = scene.camera.position;
  const Vec3 D = CameraRayDirection(x, y, canvas, scene);
  const Hit hit = ClosestIntersection(O, D, 1, cgfs::kInf, scene);
  if (hit.primitive == nullptr) {
    return {scene.background_color, -1};
  }
  return {ColorAtHit(O, D, hit, recursion_depth, scene), hit.object};
}

Color Clamped(const Color& color) {
  return glm::clamp(color, 0.0, 255.0);
}

// A value per pixel of the canvas, found by chapter 1's mapping (Canvas::ToScreen), so
// that the grid and the canvas agree about which pixel (x, y) is.
template <typename T>
class PixelGrid {
 public:
  PixelGrid(const Canvas& canvas, T value)
      : canvas_(canvas),
        cells_(static_cast<std::size_t>(canvas.Width()) * static_cast<std::size_t>(canvas.Height()),
               value) {}
  bool Contains(int x, int y) const { return canvas_.ToScreen(x, y).has_value(); }
  // The cell of pixel (x, y), which must be on the canvas.
  T& operator()(int x, int y) {
    const cgfs::ScreenPoint screen = *canvas_.ToScreen(x, y);
    return cells_[static_cast<std::size_t>(screen.row) * static_cast<std::size_t>(canvas_.Width()) +
                  static_cast<std::size_t>(screen.column)];
  }

 private:
  const Canvas& canvas_;
  std::vector<T> cells_;
};

Color SupersampledColor(int x, int y, int n, int recursion_depth, const Scene& scene,
                        const Canvas& canvas) {
  Color sum{0, 0, 0};
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const double sx = x + (i + 0.5) / n - 0.5;
      const double sy = y + (j + 0.5) / n - 0.5;
      sum += Clamped(TraceCameraRay(sx, sy, recursion_depth, scene, canvas).color);
    }
  }
  return sum / static_cast<double>(n * n);
}

}  // namespace

void RenderSceneSubsampled(const Scene& unprepared, int recursion_depth, Canvas& canvas,
                           const Optimizations& optimizations) {
  Scene scene = unprepared;
  PrepareScene(scene, optimizations);
  const int threads = optimizations.threads;
  PixelGrid<int> hit_object(canvas, -2);  // -2: not traced
  // Odd and even counted from the canvas's left and bottom edges.
  auto odd_x = [&](int x) { return (x + canvas.Width() / 2) % 2 != 0; };
  auto odd_y = [&](int y) { return (y + canvas.Height() / 2) % 2 != 0; };
  auto traced = [&](int x, int y) { return !odd_x(x) && !odd_y(y); };

  ForEachPixel(canvas, threads, [&](int x, int y) {
    if (traced(x, y)) {
      const Sample sample = TraceCameraRay(x, y, recursion_depth, scene, canvas);
      hit_object(x, y) = sample.object;
      canvas.PutPixel(x, y, sample.color);
    }
  });

  ForEachPixel(canvas, threads, [&](int x, int y) {
    if (traced(x, y)) {
      return;
    }
    // The traced pixels around this one: left and right, below and above, or the
    // four corners of the square it is the middle of.
    // -1: all saw the background; -3: they disagree, or one is off the canvas.
    const int dx = odd_x(x) ? 1 : 0;
    const int dy = odd_y(y) ? 1 : 0;
    int common = -2;
    for (const auto& [nx, ny] :
         {std::pair{x - dx, y - dy}, {x + dx, y - dy}, {x - dx, y + dy}, {x + dx, y + dy}}) {
      const int object = hit_object.Contains(nx, ny) ? hit_object(nx, ny) : -3;
      common = (common == -2 || common == object) ? object : -3;
    }
    if (common == -1) {
      canvas.PutPixel(x, y, scene.background_color);
      return;
    }
    if (common >= 0) {
      const Vec3 O = scene.camera.position;
      const Vec3 D = CameraRayDirection(x, y, canvas, scene);
      Hit hit = scene.objects[common]->Intersect(MakeRay(O, D, scene), 1, cgfs::kInf);
      if (hit.primitive != nullptr) {
        hit.object = common;
        canvas.PutPixel(x, y, ColorAtHit(O, D, hit, recursion_depth, scene));
        return;
      }
    }
    canvas.PutPixel(x, y, TraceCameraRay(x, y, recursion_depth, scene, canvas).color);
  });
}

void RenderSceneSupersampled(const Scene& scene, int recursion_depth, int n, Canvas& canvas,
                             const Optimizations& optimizations) {
  Scene prepared = scene;
  PrepareScene(prepared, optimizations);
  ForEachPixel(canvas, prepared.optimizations.threads, [&](int x, int y) {
    canvas.PutPixel(x, y, SupersampledColor(x, y, n, recursion_depth, prepared, canvas));
  });
}

cgfs::Count RenderSceneAdaptive(const Scene& scene, int recursion_depth, Canvas& canvas,
                                const Optimizations& optimizations) {
  Scene prepared = scene;
  PrepareScene(prepared, optimizations);
  const int threads = prepared.optimizations.threads;
  PixelGrid<Sample> samples(canvas, Sample{});
  ForEachPixel(canvas, threads, [&](int x, int y) {
    Sample sample = TraceCameraRay(x, y, recursion_depth, prepared, canvas);
    sample.color = Clamped(sample.color);
    samples(x, y) = sample;
  });

  std::atomic<cgfs::Count> subdivided{0};
  ForEachPixel(canvas, threads, [&](int x, int y) {
    const Sample& here = samples(x, y);
    bool differs = false;
    for (const auto& [nx, ny] : {std::pair{x - 1, y}, {x + 1, y}, {x, y - 1}, {x, y + 1}}) {
      if (!samples.Contains(nx, ny)) {
        continue;
      }
      const Sample& there = samples(nx, ny);
      const Color difference = glm::abs(there.color - here.color);
      differs = differs || there.object != here.object ||
                std::max({difference.r, difference.g, difference.b}) > kAdaptiveThreshold;
    }
    if (differs) {
      ++subdivided;
      canvas.PutPixel(x, y, SupersampledColor(x, y, 4, recursion_depth, prepared, canvas));
    } else {
      canvas.PutPixel(x, y, here.color);
    }
  });
  return subdivided;
}

void RenderSceneAsChosen(const Scene& scene, int recursion_depth, Canvas& canvas,
                         const Optimizations& optimizations) {
  if (optimizations.subsampling) {
    RenderSceneSubsampled(scene, recursion_depth, canvas, optimizations);
  } else {
    RenderScene(scene, recursion_depth, canvas, optimizations);
  }
}
