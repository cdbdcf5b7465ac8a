#include "rasterizer.h"

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
  const double a = (d1 - d0) / (i1 - i0);
  for (int i = i0; i <= i1; ++i) {
    values.push_back(d0 + a * (i - i0));
  }
  return values;
}

// Listing 6-2. Pick the independent variable with more distinct values, so every
// step along it draws exactly one pixel and the segment has no gaps. Interpolated
// coordinates are truncated toward zero (spec §1.1).
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

// "Drawing Wireframe Triangles".
void DrawWireframeTriangle(Point P0, Point P1, Point P2, const Color& color, Canvas& canvas) {
  DrawLine(P0, P1, color, canvas);
  DrawLine(P1, P2, color, canvas);
  DrawLine(P2, P0, color, canvas);
}

// Listing 7-1. For each y, x_left and x_right come from the edges: the long side
// P0-P2 on one hand, the two short sides P0-P1 and P1-P2 joined on the other.
void DrawFilledTriangle(Point P0, Point P1, Point P2, const Color& color, Canvas& canvas) {
  // Sort the points so that y0 <= y1 <= y2.
  if (P1.y < P0.y) {
    std::swap(P1, P0);
  }
  if (P2.y < P0.y) {
    std::swap(P2, P0);
  }
  if (P2.y < P1.y) {
    std::swap(P2, P1);
  }

  // Compute the x coordinates of the triangle edges, with y as the independent variable.
  std::vector<double> x01 = Interpolate(P0.y, P0.x, P1.y, P1.x);
  const std::vector<double> x12 = Interpolate(P1.y, P1.x, P2.y, P2.x);
  const std::vector<double> x02 = Interpolate(P0.y, P0.x, P2.y, P2.x);

  // Concatenate the short sides. The x at y1 ends x01 and starts x12: keep it once.
  x01.pop_back();
  std::vector<double> x012 = x01;
  x012.insert(x012.end(), x12.begin(), x12.end());

  // Determine which is left and which is right, on the middle row.
  const std::size_t m = x012.size() / 2;
  const bool long_side_is_left = x02[m] < x012[m];
  const std::vector<double>& x_left = long_side_is_left ? x02 : x012;
  const std::vector<double>& x_right = long_side_is_left ? x012 : x02;

  // Draw the horizontal segments. The ends are truncated toward zero; should
  // rounding ever put the left end right of the right one, the row stays empty.
  for (int y = P0.y; y <= P2.y; ++y) {
    const int x_l = static_cast<int>(x_left[y - P0.y]);
    const int x_r = static_cast<int>(x_right[y - P0.y]);
    for (int x = x_l; x <= x_r; ++x) {
      canvas.PutPixel(x, y, color);
    }
  }
}

// Listing 8-1. The same steps as DrawFilledTriangle, with h carried along. The
// vertices move as a whole when sorted, so each keeps its own h.
void DrawShadedTriangle(Point P0, Point P1, Point P2, const Color& color, Canvas& canvas) {
  // Sort the points so that y0 <= y1 <= y2.
  if (P1.y < P0.y) {
    std::swap(P1, P0);
  }
  if (P2.y < P0.y) {
    std::swap(P2, P0);
  }
  if (P2.y < P1.y) {
    std::swap(P2, P1);
  }

  // Compute the x coordinates and h values of the triangle edges.
  std::vector<double> x01 = Interpolate(P0.y, P0.x, P1.y, P1.x);
  std::vector<double> h01 = Interpolate(P0.y, P0.h, P1.y, P1.h);

  const std::vector<double> x12 = Interpolate(P1.y, P1.x, P2.y, P2.x);
  const std::vector<double> h12 = Interpolate(P1.y, P1.h, P2.y, P2.h);

  const std::vector<double> x02 = Interpolate(P0.y, P0.x, P2.y, P2.x);
  const std::vector<double> h02 = Interpolate(P0.y, P0.h, P2.y, P2.h);

  // Concatenate the short sides.
  x01.pop_back();
  std::vector<double> x012 = x01;
  x012.insert(x012.end(), x12.begin(), x12.end());

  h01.pop_back();
  std::vector<double> h012 = h01;
  h012.insert(h012.end(), h12.begin(), h12.end());

  // Determine which is left and which is right, by x only: h follows that choice.
  const std::size_t m = x012.size() / 2;
  const bool long_side_is_left = x02[m] < x012[m];
  const std::vector<double>& x_left = long_side_is_left ? x02 : x012;
  const std::vector<double>& h_left = long_side_is_left ? h02 : h012;
  const std::vector<double>& x_right = long_side_is_left ? x012 : x02;
  const std::vector<double>& h_right = long_side_is_left ? h012 : h02;

  // Draw the horizontal segments, interpolating h across each one.
  for (int y = P0.y; y <= P2.y; ++y) {
    const int x_l = static_cast<int>(x_left[y - P0.y]);
    const int x_r = static_cast<int>(x_right[y - P0.y]);

    const std::vector<double> h_segment =
        Interpolate(x_l, h_left[y - P0.y], x_r, h_right[y - P0.y]);
    for (int x = x_l; x <= x_r; ++x) {
      const Color shaded_color = color * h_segment[x - x_l];
      canvas.PutPixel(x, y, shaded_color);
    }
  }
}
