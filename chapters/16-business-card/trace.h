// The card's tracer, its function T: the nearest thing a ray hits.
#pragma once

#include <glm/vec3.hpp>

// What a ray hits first (the card returns 0, 1 or 2).
enum class HitType { Sky, Floor, Sphere };

// Hits nearer than this are ignored, so that a ray leaving a surface does not hit
// the surface it leaves.
inline constexpr double kMinDistance = 0.01;

// The nearest hit of the ray o + t·d (d of unit length) with the floor or a sphere of
// the letters. On a hit, writes its distance to `t` and the surface normal there to
// `n` (the card's commentary calls n a "half vector"; it is the normal); on Sky, t is
// 1e9 and n is left as it was.
//
// `bounded`: test the box around each letter first (bound.h), and skip its spheres
// when the ray misses it. The result is the same either way; only the time differs.
HitType Trace(const glm::dvec3& o, const glm::dvec3& d, double& t, glm::dvec3& n,
              bool bounded = false);
