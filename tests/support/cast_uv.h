// The texture coordinates at the point a cast ray hit (ray_caster.h), for the chapters
// with textures: included by their tests, so that `Scene` and `Triangle` are theirs.
#pragma once

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "ray_caster.h"

namespace cgfs::test {

// Its triangle's corners' (u, v) weighted by the point's barycentric coordinates
// (exact, whatever the perspective).
template <typename Scene>
glm::dvec2 CastUV(const Scene& scene, const CastScene& cast_scene, const CastHit& hit) {
  const auto& T = scene.instances[static_cast<std::size_t>(hit.instance)]
                      .model->triangles[static_cast<std::size_t>(hit.triangle)];
  const CastTriangle* placed =
      &cast_scene.triangles[cast_scene.instances[static_cast<std::size_t>(hit.instance)].first +
                            static_cast<std::size_t>(hit.triangle)];
  const glm::dvec3 e1 = placed->b - placed->a;
  const glm::dvec3 e2 = placed->c - placed->a;
  const glm::dvec3 p = hit.point - placed->a;
  const double d11 = glm::dot(e1, e1), d12 = glm::dot(e1, e2), d22 = glm::dot(e2, e2);
  const double p1 = glm::dot(p, e1), p2 = glm::dot(p, e2);
  const double det = d11 * d22 - d12 * d12;
  const double b1 = (d22 * p1 - d12 * p2) / det;
  const double b2 = (d11 * p2 - d12 * p1) / det;
  return (1 - b1 - b2) * T.uvs[0] + b1 * T.uvs[1] + b2 * T.uvs[2];
}

}  // namespace cgfs::test
