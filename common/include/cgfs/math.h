// Vectors and matrices come from GLM (double precision); this header adds only the
// names the book's appendix uses that GLM does not have.
#pragma once

#include <limits>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace cgfs {

using Vec3 = glm::dvec3;

// The book's "inf": no upper limit for t.
inline constexpr double kInf = std::numeric_limits<double>::infinity();

// Appendix, "Homogeneous coordinates": (x, y, z, w) is the point (x/w, y/w, z/w).
inline Vec3 ToCartesian(const glm::dvec4& homogeneous) {
  return Vec3(homogeneous) / homogeneous.w;
}

}  // namespace cgfs
