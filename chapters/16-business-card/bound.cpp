#include "bound.h"

#include <algorithm>
#include <utility>

#include <glm/common.hpp>

#include "letters.h"
#include "trace.h"

const std::vector<LetterBound>& LetterBounds() {
  static const std::vector<LetterBound> letters = [] {
    // LetterSpheres() goes column by column from k = 18 down, so a letter's spheres
    // follow one another, and a new letter starts where a column was skipped.
    const auto& spheres = LetterSpheres();
    std::vector<LetterBound> found;
    for (int i = 0; i < kLetterSphereCount; ++i) {
      const glm::dvec3& centre = spheres[static_cast<std::size_t>(i)];
      if (found.empty() || spheres[static_cast<std::size_t>(i - 1)].x - centre.x > 1) {
        found.push_back({{centre, centre}, i, 0});
      }
      LetterBound& letter = found.back();
      letter.box.min = glm::min(letter.box.min, centre);
      letter.box.max = glm::max(letter.box.max, centre);
      ++letter.count;
    }
    const glm::dvec3 reach(1 + kBoundMargin);  // the unit radius, and the margin
    for (LetterBound& letter : found) {
      letter.box.min -= reach;
      letter.box.max += reach;
    }
    return found;
  }();
  return letters;
}

bool MayHit(const Box& box, const glm::dvec3& o, const glm::dvec3& d, double t) {
  double enter = kMinDistance;
  double leave = t;
  for (int axis = 0; axis < 3; ++axis) {
    if (d[axis] == 0) {
      // Parallel to this pair of planes: between them for ever, or never.
      if (o[axis] < box.min[axis] || o[axis] > box.max[axis]) {
        return false;
      }
      continue;
    }
    double near = (box.min[axis] - o[axis]) / d[axis];
    double far = (box.max[axis] - o[axis]) / d[axis];
    if (near > far) {
      std::swap(near, far);
    }
    enter = std::max(enter, near);
    leave = std::min(leave, far);
    if (enter > leave) {
      return false;
    }
  }
  return true;
}
