// The card's sampler, its function S: the colour seen along one ray.
#pragma once

#include <glm/vec3.hpp>

#include "random.h"

// Colours here are the card's: about 0..1 for the sky, and up to 3 for a lit floor
// tile; Render scales them to 0..255.
using CardColor = glm::dvec3;

// The sky seen in direction d: (0.7, 0.6, 1.0)·(1 − d.z)⁴, lavender at the horizon
// and darker upwards, black straight up.
CardColor SkyColor(const glm::dvec3& d);

// The colour of the floor's tile at the point h: 5 × 5 squares, red (3, 1, 1) where
// ⌈h.x/5⌉ + ⌈h.y/5⌉ is odd and white (3, 3, 3) where it is even.
CardColor FloorTile(const glm::dvec3& h);

// Where the light is: a 1 × 1 square light at height 16, [9, 10] × [9, 10] × {16};
// each sample aims its shadow ray at a random point of it, which makes the shadows soft.
inline constexpr double kLightX = 9, kLightY = 9, kLightZ = 16;

// The mirror spheres reflect recursively; after this many reflections a ray stops
// (the card has no limit). Each reflection halves what it adds, so the limit changes
// a pixel by less than one level.
inline constexpr int kMaxReflections = 10;

// The colour seen from o in the direction d (of unit length):
//   - the sky if the ray hits nothing;
//   - on the floor, its tile lit by Lambert's cosine b (0 in shadow) plus 0.1
//     ambient: tile·(0.2·b + 0.1);
//   - on a sphere, a white highlight p = ⟨l, r⟩⁹⁹ (0 in shadow) plus half of what
//     the reflected ray r sees: a pure mirror.
// Random numbers, in this order: the light point's x, then its y, for every hit.
// `reflections` counts the reflections so far; `bounded` is passed to Trace.
CardColor Sample(const glm::dvec3& o, const glm::dvec3& d, Random& random, bool bounded = false,
                 int reflections = 0);
