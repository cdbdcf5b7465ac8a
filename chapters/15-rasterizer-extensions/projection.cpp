#include "projection.h"

#include <cassert>

namespace {

// Truncated toward zero (docs/conventions.md, "Rounding"), and held within int's range:
// a point far off the canvas, or no number at all, must not make the cast undefined.
int ToPixel(double value) {
  constexpr int kLimit = 1 << 30;
  if (value > -kLimit && value < kLimit) {
    return static_cast<int>(value);
  }
  return value > 0 ? kLimit : -kLimit;
}

}  // namespace

// Listing 9-1. Scale viewport units to pixels.
Point ViewportToCanvas(double x, double y, const Canvas& canvas, const Viewport& viewport) {
  return {ToPixel(x * canvas.Width() / viewport.width),
          ToPixel(y * canvas.Height() / viewport.height)};
}

// Listing 9-1, "Finding P'": similar triangles give P'x = Px * d / Pz, P'y = Py * d / Pz.
Point ProjectVertex(const Vec3& v, const Canvas& canvas, const Viewport& viewport) {
  const double d = viewport.distance;
  assert(v.z >= d && "ProjectVertex: the point is in front of the projection plane");
  return ViewportToCanvas(v.x * d / v.z, v.y * d / v.z, canvas, viewport);
}
