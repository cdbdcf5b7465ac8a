#include "sampling.h"

#include <algorithm>
#include <atomic>
#include <vector>

#include "cost.h"
#include "parallel.h"

namespace {

// What one primary ray found: its colour and the scene object it hit (-1: none).
struct Sample {
  Color color;
  int object = -1;
};

Sample TraceCameraRay(double x, double y, int recursion_depth, const Scene& scene,
                      const Canvas& canvas) {
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

// Per pixel storage in canvas coordinates.
template <typename T>
class PixelGrid {
 public:
  PixelGrid(const Canvas& canvas, T value)
      : width_(canvas.Width()), height_(canvas.Height()), cells_(width_ * height_, value) {}
  bool Contains(int x, int y) const {
    return -width_ / 2 <= x && x < width_ / 2 && -height_ / 2 <= y && y < height_ / 2;
  }
  T& operator()(int x, int y) { return cells_[(y + height_ / 2) * width_ + (x + width_ / 2)]; }

 private:
  int width_;
  int height_;
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
                           const Optimizations& optimizations, std::vector<long>* searches) {
  Scene scene = unprepared;
  PrepareScene(scene, optimizations);
  const int threads = optimizations.threads;
  PixelGrid<int> hit_object(canvas, -2);  // -2: not traced
  // Odd and even counted from the canvas's left and bottom edges.
  auto odd_x = [&](int x) { return (x + canvas.Width() / 2) % 2 != 0; };
  auto odd_y = [&](int y) { return (y + canvas.Height() / 2) % 2 != 0; };
  auto traced = [&](int x, int y) { return !odd_x(x) && !odd_y(y); };

  ForEachTile(canvas.Width(), canvas.Height(), threads, [&](const Tile& tile) {
    for (int x = tile.x_begin; x < tile.x_end; ++x) {
      for (int y = tile.y_begin; y < tile.y_end; ++y) {
        if (searches != nullptr) {
          (*searches)[PixelIndex(x, y, canvas)] = traced(x, y) ? 1 : 0;
        }
        if (traced(x, y)) {
          const Sample sample = TraceCameraRay(x, y, recursion_depth, scene, canvas);
          hit_object(x, y) = sample.object;
          canvas.PutPixel(x, y, sample.color);
        }
      }
    }
  });

  ForEachTile(canvas.Width(), canvas.Height(), threads, [&](const Tile& tile) {
    for (int x = tile.x_begin; x < tile.x_end; ++x) {
      for (int y = tile.y_begin; y < tile.y_end; ++y) {
        if (traced(x, y)) {
          continue;
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
        const Vec3 O = scene.camera.position;
        const Vec3 D = CameraRayDirection(x, y, canvas, scene);
        if (common == -1) {
          canvas.PutPixel(x, y, scene.background_color);
          continue;
        }
        if (common >= 0) {
          Hit hit = scene.objects[common]->Intersect(MakeRay(O, D, scene), 1, cgfs::kInf);
          if (hit.primitive != nullptr) {
            hit.object = common;
            canvas.PutPixel(x, y, ColorAtHit(O, D, hit, recursion_depth, scene));
            continue;
          }
        }
        if (searches != nullptr) {
          (*searches)[PixelIndex(x, y, canvas)] = 1;
        }
        canvas.PutPixel(x, y, TraceRay(O, D, 1, cgfs::kInf, recursion_depth, scene));
      }
    }
  });
}

void RenderSceneSupersampled(const Scene& scene, int recursion_depth, int n, Canvas& canvas,
                             const Optimizations& optimizations) {
  Scene prepared = scene;
  PrepareScene(prepared, optimizations);
  ForEachTile(
      canvas.Width(), canvas.Height(), prepared.optimizations.threads, [&](const Tile& tile) {
        for (int x = tile.x_begin; x < tile.x_end; ++x) {
          for (int y = tile.y_begin; y < tile.y_end; ++y) {
            canvas.PutPixel(x, y, SupersampledColor(x, y, n, recursion_depth, prepared, canvas));
          }
        }
      });
}

long RenderSceneAdaptive(const Scene& scene, int recursion_depth, Canvas& canvas,
                         const Optimizations& optimizations, std::vector<long>* rays) {
  Scene prepared = scene;
  PrepareScene(prepared, optimizations);
  const int threads = prepared.optimizations.threads;
  PixelGrid<Sample> samples(canvas, Sample{});
  ForEachTile(canvas.Width(), canvas.Height(), threads, [&](const Tile& tile) {
    for (int x = tile.x_begin; x < tile.x_end; ++x) {
      for (int y = tile.y_begin; y < tile.y_end; ++y) {
        Sample sample = TraceCameraRay(x, y, recursion_depth, prepared, canvas);
        sample.color = Clamped(sample.color);
        samples(x, y) = sample;
      }
    }
  });

  std::atomic<long> subdivided{0};
  ForEachTile(canvas.Width(), canvas.Height(), threads, [&](const Tile& tile) {
    for (int x = tile.x_begin; x < tile.x_end; ++x) {
      for (int y = tile.y_begin; y < tile.y_end; ++y) {
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
        if (rays != nullptr) {
          (*rays)[PixelIndex(x, y, canvas)] = differs ? 1 + 16 : 1;
        }
        if (differs) {
          ++subdivided;
          canvas.PutPixel(x, y, SupersampledColor(x, y, 4, recursion_depth, prepared, canvas));
        } else {
          canvas.PutPixel(x, y, here.color);
        }
      }
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
