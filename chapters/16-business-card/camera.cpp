#include "camera.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace {

// The card's pixel step at 512 pixels: the image plane, one unit in front of the
// eye, is 1.024 units wide (a field of view of 2·atan(0.512), about 54°).
constexpr double kCardPixelStep = 0.002;
constexpr double kCardAperture = 99;

// Turns `forward` by `degrees` towards `side`, and `side` with it (both unit vectors at
// right angles): a rotation in their plane. An angle of 0 leaves both exactly as they
// were (cos 0 = 1, sin 0 = 0), so the card's own view is its own vectors.
void Turn(glm::dvec3& forward, glm::dvec3& side, double degrees) {
  const double cos = std::cos(glm::radians(degrees));
  const double sin = std::sin(glm::radians(degrees));
  const glm::dvec3 turned = forward * cos + side * sin;
  side = side * cos - forward * sin;
  forward = turned;
}

}  // namespace

Camera MakeCamera(int width, int height, const cgfs::View& view) {
  // At 512 pixels the scale is 1, and a, b, c and the aperture are the card's.
  const double scale = static_cast<double>(kCardSide) / width;
  const double step = kCardPixelStep * scale;
  const glm::dvec3 up(0, 0, 1);
  // The card's directions, each of length 1: forward, to the image's left, and up.
  glm::dvec3 g = glm::normalize(glm::dvec3(-6, -16, 0));
  glm::dvec3 left = glm::normalize(glm::cross(up, g));
  glm::dvec3 above = glm::normalize(glm::cross(g, left * step));
  Camera camera;
  camera.eye = kEye - left * view.move.x + above * view.move.y + g * view.move.z;
  Turn(g, left, view.yaw);
  Turn(g, above, view.pitch);
  camera.g = g;
  camera.a = left * step;
  camera.b = above * step;
  camera.c = (camera.a * (width / 2.0) + camera.b * (height / 2.0)) * -1.0 + camera.g;
  camera.aperture = kCardAperture / scale;  // the same lens at every size
  return camera;
}
