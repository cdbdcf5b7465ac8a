#include "projection.h"

#include <cassert>

// Listing 9-1. Scale viewport units to pixels.
Point ViewportToCanvas(double x, double y, const Canvas& canvas, const Viewport& viewport) {
  return {static_cast<int>(x * canvas.Width() / viewport.width),
          static_cast<int>(y * canvas.Height() / viewport.height)};
}

// Listing 9-1, "Finding P'": similar triangles give P'x = Px * d / Pz, P'y = Py * d / Pz.
Point ProjectVertex(const Vec3& v, const Canvas& canvas, const Viewport& viewport) {
  const double d = viewport.distance;
  assert(v.z >= d && "ProjectVertex: the point is in front of the projection plane");
  return ViewportToCanvas(v.x * d / v.z, v.y * d / v.z, canvas, viewport);
}
