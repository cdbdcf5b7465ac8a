#include "matrices.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

glm::dmat4 MakeTranslationMatrix(const Vec3& translation) {
  return glm::translate(glm::dmat4(1.0), translation);
}

glm::dmat4 MakeScalingMatrix(double scale) {
  return glm::scale(glm::dmat4(1.0), Vec3(scale));
}

glm::dmat4 MakeOYRotationMatrix(double degrees) {
  // GLM turns counterclockwise about +Y in a right-handed frame, taking +Z towards
  // +X; the book's matrix turns the other way (its scene axes are left-handed).
  return glm::rotate(glm::dmat4(1.0), glm::radians(-degrees), Vec3(0, 1, 0));
}
