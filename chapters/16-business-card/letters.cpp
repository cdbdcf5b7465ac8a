#include "letters.h"

bool HasSphere(int k, int j) {
  return (kLetterRows[static_cast<std::size_t>(j)] & (1U << k)) != 0;
}

glm::dvec3 SphereCentre(int k, int j) {
  return {k, 0, j + 4};
}

const std::array<glm::dvec3, kLetterSphereCount>& LetterSpheres() {
  static const std::array<glm::dvec3, kLetterSphereCount> spheres = [] {
    std::array<glm::dvec3, kLetterSphereCount> centres{};
    std::size_t count = 0;
    for (int k = kLetterColumns - 1; k >= 0; --k) {
      for (int j = static_cast<int>(kLetterRows.size()) - 1; j >= 0; --j) {
        if (HasSphere(k, j)) {
          centres.at(count++) = SphereCentre(k, j);  // at(): a 50th bit would throw
        }
      }
    }
    return centres;
  }();
  return spheres;
}
