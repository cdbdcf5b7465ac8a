#include "bound.h"

#include <algorithm>
#include <utility>

#include <glm/common.hpp>

#include "letters.h"
#include "trace.h"

namespace {

bool ColumnIsEmpty(int k) {
  for (int j = 0; j < static_cast<int>(kLetterRows.size()); ++j) {
    if (HasSphere(k, j)) {
      return false;
    }
  }
  return true;
}

}  // namespace

const std::vector<LetterBound>& LetterBounds() {
  static const std::vector<LetterBound> letters = [] {
    std::vector<LetterBound> found;
    const auto& spheres = LetterSpheres();
    int next = 0;  // the next sphere of LetterSpheres(), which go from column 18 down
    bool in_letter = false;
    for (int k = kLetterColumns - 1; k >= 0; --k) {
      if (ColumnIsEmpty(k)) {
        in_letter = false;
        continue;
      }
      if (!in_letter) {
        found.push_back(
            {{spheres[static_cast<std::size_t>(next)], spheres[static_cast<std::size_t>(next)]},
             next,
             0});
        in_letter = true;
      }
      LetterBound& letter = found.back();
      for (; next < kLetterSphereCount && spheres[static_cast<std::size_t>(next)].x == k; ++next) {
        letter.box.min = glm::min(letter.box.min, spheres[static_cast<std::size_t>(next)]);
        letter.box.max = glm::max(letter.box.max, spheres[static_cast<std::size_t>(next)]);
        ++letter.count;
      }
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
