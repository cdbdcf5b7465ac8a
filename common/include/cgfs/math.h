// Vectors come from GLM (double precision); this header adds only the names
// the book uses that GLM does not have.
#pragma once

#include <limits>

#include <glm/geometric.hpp>
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

// Chapter 10, "Homogeneous Coordinates": 4x4 transforms, acting on column vectors
// (v' = M * v; in A * B, B acts first). Test them by what they do to vectors:
// GLM stores matrices column by column.

// Moves a point (w = 1) by `translation`; leaves a direction (w = 0) alone.
glm::dmat4 MakeTranslationMatrix(const Vec3& translation);

// Scales about the origin, the same in every direction or per axis.
glm::dmat4 MakeScalingMatrix(double scale);
glm::dmat4 MakeScalingMatrix(const Vec3& scale);

// Rotation about the Y axis, as the author's demos define it:
//   [[cos, 0, -sin], [0, 1, 0], [sin, 0, cos]]
// so OY(90) turns +Z into -X and +X into +Z.
glm::dmat4 MakeOYRotationMatrix(double degrees);

}  // namespace cgfs
