// "Refraction": a ray that crosses into another material bends (Snell's law,
// sin a1 / sin a2 = n2 / n1, the angles measured from the normal).
#pragma once

#include <optional>

#include "cgfs/math.h"

using cgfs::Vec3;

// The refractive index of the space between objects.
inline constexpr double kAirIndex = 1.0;

// The direction a ray along D takes after crossing a surface with unit normal N
// (on the side D comes from) from a medium of index n1 into one of index n2; unit
// length. Empty on total internal reflection, when no refracted ray exists.
std::optional<Vec3> RefractRay(const Vec3& D, const Vec3& N, double n1, double n2);
