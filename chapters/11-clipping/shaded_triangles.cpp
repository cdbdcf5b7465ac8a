#include "shaded_triangles.h"

#include <utility>
#include <vector>

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
