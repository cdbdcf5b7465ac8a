#include "lines.h"

#include <algorithm>
#include <cstdlib>
#include <utility>

// "Linear Interpolation". The book accumulates d = d + a, which drifts: after
// hundreds of steps the last value can land just below a whole number and be
// truncated one pixel short. d0 + a*k is the same function without the drift.
std::vector<double> Interpolate(int i0, double d0, int i1, double d1) {
  if (i0 == i1) {
    return {d0};
  }
  std::vector<double> values;
  values.reserve(static_cast<std::size_t>(std::max(0, i1 - i0 + 1)));  // one allocation
  const double a = (d1 - d0) / (i1 - i0);
  for (int i = i0; i <= i1; ++i) {
    values.push_back(d0 + a * (i - i0));
  }
  return values;
}

// Listing 6-2. Pick the independent variable with more distinct values, so every
// step along it draws exactly one pixel and the segment has no gaps. Interpolated
// coordinates are truncated toward zero (docs/conventions.md, "Rounding").
void DrawLine(Point P0, Point P1, const Color& color, Canvas& canvas) {
  if (std::abs(P1.x - P0.x) > std::abs(P1.y - P0.y)) {
    // The line is horizontal-ish: y = f(x). Make sure x0 < x1.
    if (P0.x > P1.x) {
      std::swap(P0, P1);
    }
    const std::vector<double> ys = Interpolate(P0.x, P0.y, P1.x, P1.y);
    for (int x = P0.x; x <= P1.x; ++x) {
      canvas.PutPixel(x, static_cast<int>(ys[x - P0.x]), color);
    }
  } else {
    // The line is vertical-ish: x = f(y). Make sure y0 < y1.
    if (P0.y > P1.y) {
      std::swap(P0, P1);
    }
    const std::vector<double> xs = Interpolate(P0.y, P0.x, P1.y, P1.x);
    for (int y = P0.y; y <= P1.y; ++y) {
      canvas.PutPixel(static_cast<int>(xs[y - P0.y]), y, color);
    }
  }
}
