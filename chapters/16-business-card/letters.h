// The card's scene: 49 mirror spheres that spell "aek", Andrew Kensler's initials,
// standing on a floor. The world has Z up (unlike the book, where Y is up); the floor
// is the plane z = 0.
#pragma once

#include <array>
#include <cstdint>

#include <glm/vec3.hpp>

// The card's array G: a bitmap of 9 rows (j = 0..8, bottom to top) and 19 columns
// (k = 0..18). Bit k of row j set means a unit sphere centred at (k, 0, j + 4).
// Seen from the card's camera, a larger k is further left, so the letters read
// "aek" from left to right (chapters/16-business-card/README.md draws the bitmap).
inline constexpr std::array<std::uint32_t, 9> kLetterRows = {247570, 280596, 280600, 249748, 18578,
                                                             18577,  231184, 16,     16};

inline constexpr int kLetterColumns = 19;
inline constexpr int kLetterSphereCount = 49;  // the bits set in kLetterRows

// Whether bit k of row j is set: whether the bitmap has a sphere there.
bool HasSphere(int k, int j);

// The centre of the sphere of bit k of row j: (k, 0, j + 4).
glm::dvec3 SphereCentre(int k, int j);

// Every sphere's centre, in the order the card's Trace tries them: k from 18 down
// to 0, and for each k, j from 8 down to 0. (The order matters only when two
// spheres are hit at exactly the same distance.)
const std::array<glm::dvec3, kLetterSphereCount>& LetterSpheres();
