#include "render.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "cgfs/error.h"
#include "parallel.h"
#include "random.h"

namespace {

// The random numbers of one sample: a point on the lens and a point in the pixel, each
// in [0, 1)², and, if stratified, a point on the light for the first hit.
struct SampleNumbers {
  double lens_a, lens_b;
  double pixel_x, pixel_y;
  bool has_light = false;
  double light_x = 0, light_y = 0;
};

// The card's: R() for each, in the card's order.
SampleNumbers CardNumbers(Random& random) {
  SampleNumbers numbers{};
  numbers.lens_a = random.Rand();
  numbers.lens_b = random.Rand();
  numbers.pixel_x = random.Rand();
  numbers.pixel_y = random.Rand();
  return numbers;
}

// Stratified (RenderSettings::stratified): n x n cells, each dimension pair through its
// own shuffle of them.
class Strata {
 public:
  Strata(int samples, Random& random) : n_(static_cast<int>(std::lround(std::sqrt(samples)))) {
    if (n_ * n_ != samples) {
      throw cgfs::Error("stratified samples must be a square number, not " +
                        std::to_string(samples));
    }
    for (std::vector<int>* cells : {&lens_, &light_}) {
      cells->resize(static_cast<std::size_t>(samples));
      for (int i = 0; i < samples; ++i) {
        (*cells)[static_cast<std::size_t>(i)] = i;
      }
      for (int i = samples - 1; i > 0; --i) {  // Fisher and Yates
        const int j = std::min(i, static_cast<int>(random.Rand() * (i + 1)));
        std::swap((*cells)[static_cast<std::size_t>(i)], (*cells)[static_cast<std::size_t>(j)]);
      }
    }
  }

  SampleNumbers Numbers(int sample, Random& random) const {
    SampleNumbers numbers{};
    Point(lens_[static_cast<std::size_t>(sample)], random, numbers.lens_a, numbers.lens_b);
    Point(sample, random, numbers.pixel_x, numbers.pixel_y);
    numbers.has_light = true;
    Point(light_[static_cast<std::size_t>(sample)], random, numbers.light_x, numbers.light_y);
    return numbers;
  }

 private:
  // A random point of cell `cell` of the n x n grid over [0, 1)².
  void Point(int cell, Random& random, double& u, double& v) const {
    u = (cell % n_ + random.Rand()) / n_;
    v = (cell / n_ + random.Rand()) / n_;
  }

  int n_;
  std::vector<int> lens_, light_;
};

}  // namespace

glm::ivec3 RenderPixel(const Camera& camera, int x, int y, const RenderSettings& settings) {
  Random random(settings.seed, x, y);
  const std::optional<Strata> strata =
      settings.stratified ? std::optional<Strata>(std::in_place, settings.samples, random)
                          : std::nullopt;
  // The card adds 64 samples of 3.5 each: 3.5 = 224 / 64. For other counts, the same
  // 224 / samples keeps 13 + 224·mean.
  const double weight = 224.0 / settings.samples;
  glm::dvec3 p(13, 13, 13);
  for (int sample = 0; sample < settings.samples; ++sample) {
    const SampleNumbers u = strata ? strata->Numbers(sample, random) : CardNumbers(random);
    const glm::dvec3 t = camera.a * (u.lens_a - 0.5) * camera.aperture +
                         camera.b * (u.lens_b - 0.5) * camera.aperture;
    const glm::dvec3 pixel_ray = camera.a * (u.pixel_x + x) + camera.b * (y + u.pixel_y) + camera.c;
    const glm::dvec3 direction = glm::normalize(t * -1.0 + pixel_ray * kFocus);
    if (u.has_light) {
      random.Preset(u.light_x, u.light_y);
    }
    p = Sample(kEye + t, direction, random, settings.optimizations.bound) * weight + p;
    random.ClearPreset();
  }
  // The card prints (int)p: truncation. Clamping is ours.
  return glm::clamp(glm::ivec3(p), glm::ivec3(0), glm::ivec3(255));
}

void Render(cgfs::Canvas& canvas, const RenderSettings& settings) {
  const int width = canvas.Width();
  const int height = canvas.Height();
  const Camera camera = MakeCamera(width, height);
  ForEachTile(width, height, settings.optimizations.threads, [&](const Tile& tile) {
    for (int cy = tile.y_begin; cy < tile.y_end; ++cy) {
      for (int cx = tile.x_begin; cx < tile.x_end; ++cx) {
        // The canvas's (cx, cy) (origin in the middle, y up) is the card's pixel
        // (x, y): the card's x grows towards the image's left.
        const int x = width / 2 - 1 - cx;
        const int y = cy + height / 2;
        canvas.PutPixel(cx, cy, cgfs::Color(RenderPixel(camera, x, y, settings)));
      }
    }
  });
}
