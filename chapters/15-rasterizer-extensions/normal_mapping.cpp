#include "normal_mapping.h"

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
