#include "depth_buffer.h"

#include <limits>
#include <stdexcept>

#include "triangle_walker.h"

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

bool DepthBuffer::Test(int x, int y, double depth) const {
  const double* stored = depths_.Find(x, y);
  if (!stored) {
    return false;
  }
  return value_ == DepthValue::kZ ? depth < *stored : depth > *stored;
}

bool DepthBuffer::Holds(int x, int y, double depth) const {
  const double* stored = depths_.Find(x, y);
  return stored && *stored == depth;
}

double DepthBuffer::At(int x, int y) const {
  const double* stored = depths_.Find(x, y);
  if (!stored) {
    throw std::out_of_range("DepthBuffer::At: the pixel is off the canvas");
  }
  return *stored;
}

// Listing 7-1 and "Depth Buffering". The depth is the one value the corners carry.
void DrawFilledTriangle(Point P0, Point P1, Point P2, double z0, double z1, double z2,
                        const Color& color, Canvas& canvas, DepthBuffer& depth_buffer) {
  const std::array<WalkerCorner<double>, 3> corners = {{{P0, depth_buffer.DepthOf(z0)},
                                                        {P1, depth_buffer.DepthOf(z1)},
                                                        {P2, depth_buffer.DepthOf(z2)}}};
  WalkTriangle(corners, [&](int x, int y, double depth) {
    if (depth_buffer.TestAndSet(x, y, depth)) {
      canvas.PutPixel(x, y, color);
    }
  });
}
