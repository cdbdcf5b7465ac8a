// The card's camera: where the eye is, where it looks, and its lens.
#pragma once

#include <glm/vec3.hpp>

#include "cgfs/view.h"

// The card's image is 512 × 512; other sizes see the same view (the pixel step
// scales with the width).
inline constexpr int kCardSide = 512;
// The eye, a little above the letters' middle, in front of them and to their right.
inline constexpr glm::dvec3 kEye{17, 16, 8};
// Every lens sample aims at the point this far along its pixel's ray (in units of
// the pixel ray (a·x + b·y + c), whose length is about 1): the focal distance.
inline constexpr double kFocus = 16;

struct Camera {
  glm::dvec3 eye = kEye;
  glm::dvec3 g;  // the viewing direction, normalize(−6, −16, 0): level, towards the letters
  glm::dvec3 a;  // one pixel along the image's x: towards the image's left (+x in the world)
  glm::dvec3 b;  // one pixel along the image's y: up, (0, 0, 0.002)
  // From the eye to the corner of pixel (0, 0): pixel (x, y) looks along a·x + b·y + c.
  glm::dvec3 c;
  double aperture = 0;  // the lens's side in pixel steps: a square of ±0.099 units
};

// The card's vectors for an image of width × height: at 512 × 512, a = normalize(up × g)
// · 0.002, b = normalize(g × a) · 0.002, c = −256·(a + b) + g, aperture 99. From `view`
// (--window, --view): the eye moved along the image's right (−a), up (b) and forward
// (g), then g, a and b turned to the left (yaw, about b) and up (pitch, about a).
Camera MakeCamera(int width, int height, const cgfs::View& view = {});
