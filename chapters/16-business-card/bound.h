// Faster, with chapter 5's "Hierarchical Structures": a box around each letter. Most
// rays (the sky above, the floor in front, most shadow rays) miss all three, and a
// ray that leaves a sphere of one letter meets at most the spheres of that letter
// and a neighbour, instead of all 49.
#pragma once

#include <vector>

#include <glm/vec3.hpp>

struct Box {
  glm::dvec3 min, max;
};

// One letter: the box around its spheres, and where they are in LetterSpheres().
struct LetterBound {
  Box box;
  int first = 0;  // its first sphere's index in LetterSpheres()
  int count = 0;  // how many spheres follow, all of this letter
};

// Each box is the smallest around its spheres (their centres ± 1), made a little
// larger so that rounding never makes it miss a ray that just touches a sphere.
inline constexpr double kBoundMargin = 1e-3;

// The letters: the bitmap's columns cut at the empty ones ("a", "e", "k": 14..18,
// 7..11 and 0..4), in the order of LetterSpheres(), whose spheres go column by column.
const std::vector<LetterBound>& LetterBounds();

// Whether the ray o + s·d can meet something inside `box` at a distance s in
// (kMinDistance, t): false only if it misses the box or meets it only outside that
// range. The slab method: the ray is inside the box between the largest entry and
// the smallest exit distance of the three pairs of planes.
bool MayHit(const Box& box, const glm::dvec3& o, const glm::dvec3& d, double t);
