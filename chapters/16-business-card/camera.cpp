#include "camera.h"

#include <glm/geometric.hpp>

namespace {

// The card's pixel step at 512 pixels: the image plane, one unit in front of the
// eye, is 1.024 units wide (a field of view of 2·atan(0.512), about 54°).
constexpr double kCardPixelStep = 0.002;
constexpr double kCardAperture = 99;

}  // namespace

Camera MakeCamera(int width, int height) {
  // At 512 pixels the scale is 1, and a, b, c and the aperture are the card's.
  const double scale = static_cast<double>(kCardSide) / width;
  const double step = kCardPixelStep * scale;
  const glm::dvec3 up(0, 0, 1);
  Camera camera;
  camera.g = glm::normalize(glm::dvec3(-6, -16, 0));
  camera.a = glm::normalize(glm::cross(up, camera.g)) * step;
  camera.b = glm::normalize(glm::cross(camera.g, camera.a)) * step;
  camera.c = (camera.a * (width / 2.0) + camera.b * (height / 2.0)) * -1.0 + camera.g;
  camera.aperture = kCardAperture / scale;  // the same lens at every size
  return camera;
}
