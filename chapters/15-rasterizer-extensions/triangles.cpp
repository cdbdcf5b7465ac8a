#include "triangles.h"

#include <utility>
#include <vector>

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
