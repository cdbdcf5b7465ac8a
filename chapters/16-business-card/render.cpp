#include "render.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

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

// Low-discrepancy (RenderSettings::stratified): the first `samples` points of the 6-D
// Sobol sequence (direction numbers of Joe and Kuo), each dimension XOR-scrambled with
// bits drawn for the pixel. Dimensions 1-2 place the sample in the pixel, 3-4 on the
// lens, 5-6 on the light: the points of any power of two fill every such pair's cells
// evenly, and the scrambling keeps neighbouring pixels from repeating one pattern.
class SobolPoints {
 public:
  SobolPoints(int samples, Random& random) {
    if (samples <= 0) {
      throw std::invalid_argument("samples per pixel must be at least 1, not " +
                                  std::to_string(samples));
    }
    for (std::uint32_t& bits : scramble_) {
      // Two draws, one statement each: the operands of | may be evaluated in either
      // order, and the bits would then depend on the compiler.
      const auto high = static_cast<std::uint32_t>(random.Rand() * 65536.0);
      const auto low = static_cast<std::uint32_t>(random.Rand() * 65536.0);
      bits = high << 16 | low;
    }
  }

  SampleNumbers Numbers(int sample) const {
    double u[6];
    for (int d = 0; d < 6; ++d) {
      std::uint32_t x = scramble_[d];
      for (int bit = 0; bit < 32 && (sample >> bit) != 0; ++bit) {
        if ((sample >> bit) & 1) {
          x ^= Directions()[d][bit];
        }
      }
      u[d] = x * 0x1p-32;
    }
    SampleNumbers numbers{};
    numbers.pixel_x = u[0];
    numbers.pixel_y = u[1];
    numbers.lens_a = u[2];
    numbers.lens_b = u[3];
    numbers.has_light = true;
    numbers.light_x = u[4];
    numbers.light_y = u[5];
    return numbers;
  }

 private:
  using Table = std::array<std::array<std::uint32_t, 32>, 6>;
  static const Table& Directions() {
    static const Table table = [] {
      Table v{};
      for (int i = 0; i < 32; ++i) {
        v[0][i] = 1U << (31 - i);  // van der Corput
      }
      // Dimensions 2 to 6: degree s, coefficients a, initial m (Joe and Kuo).
      struct Polynomial {
        int s, a;
        std::uint32_t m[4];
      };
      const Polynomial polynomials[5] = {
          {1, 0, {1}}, {2, 1, {1, 3}}, {3, 1, {1, 3, 1}}, {3, 2, {1, 1, 1}}, {4, 1, {1, 1, 3, 3}}};
      for (int d = 1; d < 6; ++d) {
        const Polynomial& p = polynomials[d - 1];
        for (int i = 0; i < 32; ++i) {
          if (i < p.s) {
            v[d][i] = p.m[i] << (31 - i);
            continue;
          }
          std::uint32_t value = v[d][i - p.s] ^ (v[d][i - p.s] >> p.s);
          for (int k = 1; k < p.s; ++k) {
            if ((p.a >> (p.s - 1 - k)) & 1) {
              value ^= v[d][i - k];
            }
          }
          v[d][i] = value;
        }
      }
      return v;
    }();
    return table;
  }

  std::uint32_t scramble_[6];
};

}  // namespace

glm::ivec3 RenderPixel(const Camera& camera, int x, int y, const RenderSettings& settings) {
  Random random(settings.seed, x, y);
  const std::optional<SobolPoints> points =
      settings.stratified ? std::optional<SobolPoints>(std::in_place, settings.samples, random)
                          : std::nullopt;
  // The card adds 64 samples of 3.5 each: 3.5 = 224 / 64. For other counts, the same
  // 224 / samples keeps 13 + 224·mean.
  const double weight = 224.0 / settings.samples;
  glm::dvec3 p(13, 13, 13);
  for (int sample = 0; sample < settings.samples; ++sample) {
    const SampleNumbers u = points ? points->Numbers(sample) : CardNumbers(random);
    const glm::dvec3 t = camera.a * (u.lens_a - 0.5) * camera.aperture +
                         camera.b * (u.lens_b - 0.5) * camera.aperture;
    const glm::dvec3 pixel_ray = camera.a * (u.pixel_x + x) + camera.b * (y + u.pixel_y) + camera.c;
    const glm::dvec3 direction = glm::normalize(t * -1.0 + pixel_ray * kFocus);
    if (u.has_light) {
      random.Preset(u.light_x, u.light_y);
    }
    p = Sample(camera.eye + t, direction, random, settings.optimizations.bound) * weight + p;
    random.ClearPreset();
  }
  // The card prints (int)p: truncation. Clamping is ours.
  return glm::clamp(glm::ivec3(p), glm::ivec3(0), glm::ivec3(255));
}

void Render(cgfs::Canvas& canvas, const RenderSettings& settings, const cgfs::View& view) {
  const int width = canvas.Width();
  const int height = canvas.Height();
  const Camera camera = MakeCamera(width, height, view);
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
