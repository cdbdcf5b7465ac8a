#include "texture.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>

Texture TextureFromImage(const cgfs::Image& image) {
  Texture texture{image.Width(), image.Height(), {}};
  texture.texels.reserve(static_cast<std::size_t>(image.Width()) *
                         static_cast<std::size_t>(image.Height()));
  for (int row = 0; row < image.Height(); ++row) {
    for (int column = 0; column < image.Width(); ++column) {
      const cgfs::Rgb8 pixel = image.At(column, row);
      texture.texels.push_back({pixel.r, pixel.g, pixel.b});
    }
  }
  return texture;
}

Texture MakeCrateTexture(int size) {
  Texture texture{size, size, {}};
  const Color light_wood(196, 140, 78);
  const Color dark_wood(132, 86, 42);
  const Color gap(58, 36, 18);
  for (int j = 0; j < size; ++j) {
    for (int i = 0; i < size; ++i) {
      // Coordinates in [0, 1), and the distance to the nearest side.
      const double x = (i + 0.5) / size;
      const double y = (j + 0.5) / size;
      const double edge = std::min({x, y, 1 - x, 1 - y});
      // Wood grain: stripes along the planks, wavy, in two shades.
      const double grain = 0.5 + 0.5 * std::sin(40 * y + 3 * std::sin(9 * x) + 7 * x);
      Color color = glm::mix(dark_wood, light_wood, 0.55 + 0.45 * grain);
      const bool frame = edge < 0.12;
      const bool brace = std::abs(x - (1 - y)) < 0.09 && !frame;
      if (frame || brace) {
        color *= 0.78;  // the frame and the brace are darker boards
      }
      // Gaps: between the frame and the planks, along the brace, between four planks.
      const bool frame_gap = std::abs(edge - 0.12) < 0.008;
      const bool brace_gap = !frame && std::abs(std::abs(x - (1 - y)) - 0.09) < 0.008;
      const bool plank_gap = !frame && !brace && std::abs(std::fmod(y, 0.25)) < 0.008;
      if (frame_gap || brace_gap || plank_gap || edge < 0.006) {
        color = gap;
      }
      // A nail near each corner of the frame.
      for (const double cx : {0.06, 0.94}) {
        for (const double cy : {0.06, 0.94}) {
          if (std::hypot(x - cx, y - cy) < 0.018) {
            color = Color(90, 90, 96);
          }
        }
      }
      texture.texels.push_back(color);
    }
  }
  return texture;
}

Texture MakeCheckerboard(int size, int cell, const Color& a, const Color& b) {
  Texture texture{size, size, {}};
  for (int j = 0; j < size; ++j) {
    for (int i = 0; i < size; ++i) {
      texture.texels.push_back((i / cell + j / cell) % 2 == 0 ? a : b);
    }
  }
  return texture;
}

namespace {

// A texel coordinate kept within [0, size], so that it can be converted to an int
// (a point just outside the triangle, or a NaN from a degenerate one, becomes the edge).
double Clamped(double t, int size) {
  return t >= 0 ? std::min(t, static_cast<double>(size)) : 0.0;
}

}  // namespace

Color GetTexelNearest(const Texture& texture, double tx, double ty) {
  tx = Clamped(tx, texture.width);
  ty = Clamped(ty, texture.height);
  return texture.At(static_cast<int>(std::floor(tx)), static_cast<int>(std::floor(ty)));
}

// "Bilinear Filtering". The book's last line is written with BT; it is CT.
Color GetTexel(const Texture& texture, double tx, double ty) {
  tx = Clamped(tx, texture.width);
  ty = Clamped(ty, texture.height);
  const double fx = tx - std::floor(tx);
  const double fy = ty - std::floor(ty);
  const int i = static_cast<int>(std::floor(tx));
  const int j = static_cast<int>(std::floor(ty));

  const Color& TL = texture.At(i, j);
  const Color& TR = texture.At(i + 1, j);
  const Color& BL = texture.At(i, j + 1);
  const Color& BR = texture.At(i + 1, j + 1);

  const Color CT = fx * TR + (1 - fx) * TL;
  const Color CB = fx * BR + (1 - fx) * BL;
  return fy * CB + (1 - fy) * CT;
}
