#include "depth_buffer.h"

#include <limits>
#include <stdexcept>

namespace {

double InitialDepth(DepthValue value) {
  return value == DepthValue::kZ ? std::numeric_limits<double>::infinity() : 0.0;
}

}  // namespace

DepthBuffer::DepthBuffer(const Canvas& canvas, DepthValue value)
    : value_(value), depths_(canvas, InitialDepth(value)) {}

double DepthBuffer::DepthOf(double z) const {
  return value_ == DepthValue::kZ ? z : 1 / z;
}

bool DepthBuffer::TestAndSet(int x, int y, double depth) {
  double* stored = depths_.Find(x, y);
  if (!stored) {
    return false;
  }
  const bool closer = value_ == DepthValue::kZ ? depth < *stored : depth > *stored;
  if (closer) {
    *stored = depth;
  }
  return closer;
}

double DepthBuffer::At(int x, int y) const {
  const double* stored = depths_.Find(x, y);
  if (!stored) {
    throw std::out_of_range("DepthBuffer::At: the pixel is off the canvas");
  }
  return *stored;
}

// "Depth Buffering": compute v01, v12 and v02, and join v01 and v12 into v012.
std::pair<std::vector<double>, std::vector<double>> EdgeInterpolate(int y0, double v0, int y1,
                                                                    double v1, int y2, double v2) {
  std::vector<double> v01 = Interpolate(y0, v0, y1, v1);
  const std::vector<double> v12 = Interpolate(y1, v1, y2, v2);
  std::vector<double> v02 = Interpolate(y0, v0, y2, v2);
  v01.pop_back();
  v01.insert(v01.end(), v12.begin(), v12.end());
  return {std::move(v02), std::move(v01)};
}

// Listing 7-1 and "Depth Buffering". The depth is one more attribute of the vertices:
// it goes along the edges and across each row like h in Listing 8-1.
void DrawFilledTriangle(Point P0, Point P1, Point P2, double z0, double z1, double z2,
                        const Color& color, Canvas& canvas, DepthBuffer& depth_buffer) {
  // Sort the points so that y0 <= y1 <= y2; each depth goes with its point.
  if (P1.y < P0.y) {
    std::swap(P1, P0);
    std::swap(z1, z0);
  }
  if (P2.y < P0.y) {
    std::swap(P2, P0);
    std::swap(z2, z0);
  }
  if (P2.y < P1.y) {
    std::swap(P2, P1);
    std::swap(z2, z1);
  }

  // The x coordinates and the depths of the triangle's edges.
  const auto [x02, x012] = EdgeInterpolate(P0.y, P0.x, P1.y, P1.x, P2.y, P2.x);
  const auto [depth02, depth012] =
      EdgeInterpolate(P0.y, depth_buffer.DepthOf(z0), P1.y, depth_buffer.DepthOf(z1), P2.y,
                      depth_buffer.DepthOf(z2));

  // Which side is left and which is right, by x on the middle row; the depth follows.
  const std::size_t m = x012.size() / 2;
  const bool long_side_is_left = x02[m] < x012[m];
  const std::vector<double>& x_left = long_side_is_left ? x02 : x012;
  const std::vector<double>& x_right = long_side_is_left ? x012 : x02;
  const std::vector<double>& depth_left = long_side_is_left ? depth02 : depth012;
  const std::vector<double>& depth_right = long_side_is_left ? depth012 : depth02;

  // Draw the horizontal segments, each pixel only where it is closer than what the
  // buffer holds. The book indexes the row's depths with x - x1; it means x - x_l.
  for (int y = P0.y; y <= P2.y; ++y) {
    const int x_l = static_cast<int>(x_left[y - P0.y]);
    const int x_r = static_cast<int>(x_right[y - P0.y]);
    const std::vector<double> depth_segment =
        Interpolate(x_l, depth_left[y - P0.y], x_r, depth_right[y - P0.y]);
    for (int x = x_l; x <= x_r; ++x) {
      if (depth_buffer.TestAndSet(x, y, depth_segment[x - x_l])) {
        canvas.PutPixel(x, y, color);
      }
    }
  }
}
