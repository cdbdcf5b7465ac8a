#include "render.h"

#include <algorithm>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "parallel.h"
#include "random.h"

glm::ivec3 RenderPixel(const Camera& camera, int x, int y, const RenderSettings& settings) {
  Random random(settings.seed, x, y);
  // The card adds 64 samples of 3.5 each: 3.5 = 224 / 64. For other counts, the same
  // 224 / samples keeps 13 + 224·mean.
  const double weight = 224.0 / settings.samples;
  glm::dvec3 p(13, 13, 13);
  for (int sample = 0; sample < settings.samples; ++sample) {
    const double lens_a = random.Rand() - 0.5;
    const double lens_b = random.Rand() - 0.5;
    const glm::dvec3 t = camera.a * lens_a * camera.aperture + camera.b * lens_b * camera.aperture;
    const double jitter_x = random.Rand();
    const double jitter_y = random.Rand();
    const glm::dvec3 pixel_ray = camera.a * (jitter_x + x) + camera.b * (y + jitter_y) + camera.c;
    const glm::dvec3 direction = glm::normalize(t * -1.0 + pixel_ray * kFocus);
    p = Sample(kEye + t, direction, random, settings.optimizations.bound) * weight + p;
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
