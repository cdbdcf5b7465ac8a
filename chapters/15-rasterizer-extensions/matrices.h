// Chapter 10, "Homogeneous Coordinates": 4x4 transforms, under the names the author's
// demos give them. They act on column vectors (v' = M * v; in A * B, B acts first);
// GLM stores matrices column by column, so test them by what they do to vectors.
#pragma once

#include <glm/mat4x4.hpp>

#include "cgfs/math.h"

using cgfs::Vec3;

// "Homogeneous Translation Matrix": moves a point (w = 1) by `translation`; leaves a
// direction (w = 0) alone.
glm::dmat4 MakeTranslationMatrix(const Vec3& translation);

// "Homogeneous Rotation and Scale Matrices": scales about the origin, the same in
// every direction (the only scale the book uses).
glm::dmat4 MakeScalingMatrix(double scale);

// Rotation about the Y axis, as the author's demos define it:
//   [[cos, 0, -sin], [0, 1, 0], [sin, 0, cos]]
// so OY(90) turns +Z into -X and +X into +Z.
glm::dmat4 MakeOYRotationMatrix(double degrees);
