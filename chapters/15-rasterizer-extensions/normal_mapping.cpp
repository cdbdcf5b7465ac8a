#include "normal_mapping.h"

#include <cmath>

Vec3 DecodeNormal(const Color& texel) {
  return 2.0 * texel / 255.0 - 1.0;
}

TangentBasis ComputeTangentBasis(const std::array<Vec3, 3>& P,
                                 const std::array<glm::dvec2, 3>& uv) {
  const Vec3 E1 = P[1] - P[0];
  const Vec3 E2 = P[2] - P[0];
  const glm::dvec2 d1 = uv[1] - uv[0];
  const glm::dvec2 d2 = uv[2] - uv[0];
  const double det = d1.x * d2.y - d2.x * d1.y;
  if (det == 0) {
    return {};
  }
  const double f = 1 / det;
  return {f * (d2.y * E1 - d1.y * E2), f * (d1.x * E2 - d2.x * E1)};
}

// Gram-Schmidt: from each vector, its parts along the ones before it removed.
Vec3 ApplyNormalMap(const Vec3& n, const TangentBasis& basis, const Vec3& N) {
  const Vec3 T = glm::normalize(basis.T - N * glm::dot(N, basis.T));
  const Vec3 B = glm::normalize(basis.B - N * glm::dot(N, basis.B) - T * glm::dot(T, basis.B));
  return glm::normalize(T * n.x + B * n.y + N * n.z);
}

Vec3 BendNormal(const Vec3& N, const Texture* normal_map, const glm::dvec2& uv,
                const TangentBasis& tangents) {
  if (!normal_map) {
    return N;
  }
  const Color texel = GetTexel(*normal_map, uv.x * normal_map->width, uv.y * normal_map->height);
  return ApplyNormalMap(DecodeNormal(texel), tangents, N);
}

// Each bump is a pyramid over its cell, h = k (1 - |x| - |y|) with x and y in [-1, 1]
// across the cell; the normal of a height field h(u, v) in tangent space is
// (-dh/du, -dh/dv, 1), normalised, here (k sign(x), k sign(y), 1) on the four faces.
// The corners between the bumps are flat. Encoded as c = 255 (n + 1) / 2, rounded.
Texture MakeDiamondNormalMap(int size, int bumps) {
  Texture texture{size, size, {}};
  const double cell = static_cast<double>(size) / bumps;
  for (int j = 0; j < size; ++j) {
    for (int i = 0; i < size; ++i) {
      const double x = std::fmod(i + 0.5, cell) / cell * 2 - 1;
      const double y = std::fmod(j + 0.5, cell) / cell * 2 - 1;
      Vec3 n(0, 0, 1);
      if (std::abs(x) + std::abs(y) < 1) {
        const double k = 0.75;  // the faces lean 47 degrees from the surface
        n = glm::normalize(Vec3(x > 0 ? k : -k, y > 0 ? k : -k, 1));
      }
      texture.texels.push_back(glm::round(255.0 * (n + 1.0) / 2.0));
    }
  }
  return texture;
}

Texture MakeDiamondTiles(int size, int bumps) {
  Texture texture{size, size, {}};
  const double cell = static_cast<double>(size) / bumps;
  const Color stone(214, 192, 152);
  const Color grout(104, 88, 72);
  for (int j = 0; j < size; ++j) {
    for (int i = 0; i < size; ++i) {
      const double x = std::fmod(i + 0.5, cell) / cell * 2 - 1;
      const double y = std::fmod(j + 0.5, cell) / cell * 2 - 1;
      const bool on_a_bump = std::abs(x) + std::abs(y) < 1;
      const bool lighter =
          (static_cast<int>((i + 0.5) / cell) + static_cast<int>((j + 0.5) / cell)) % 2 == 0;
      texture.texels.push_back(on_a_bump ? stone * (lighter ? 1.0 : 0.88) : grout);
    }
  }
  return texture;
}
