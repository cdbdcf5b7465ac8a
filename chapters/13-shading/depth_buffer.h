// Chapter 12, "Depth Buffering" and "Using 1/Z Instead of Z": a depth for every pixel
// of the canvas, and filled triangles that only cover what is farther away.
#pragma once

#include <utility>
#include <vector>

#include "canvas_grid.h"
#include "triangles.h"

// What the depth buffer stores for a point at camera-space depth z. The book tries
// z first; z is not linear across the canvas, so interpolating it between the
// vertices gives wrong depths inside a triangle. 1/z is linear, and is the answer.
enum class DepthValue { kZ, kInverseZ };

// "Depth Buffering": one number per pixel of the canvas, the depth of the point
// that pixel shows. The initial value and the comparison belong together (mixing
// z's with 1/z's would draw nothing or everything), so both live here:
//   kZ:        starts at +infinity, a point is closer when its z is smaller;
//   kInverseZ: starts at 0 (1/infinity), a point is closer when its 1/z is greater.
class DepthBuffer {
 public:
  DepthBuffer(const Canvas& canvas, DepthValue value);

  DepthValue Value() const { return value_; }

  // The number this buffer compares for a camera-space depth z: z or 1/z.
  double DepthOf(double z) const;

  // The book's pixel loop:
  //   if (depth is closer than depth_buffer[x][y]) { PutPixel(x, y, ...); depth_buffer[x][y] =
  //   depth }
  // True (and the depth stored) when `depth` is strictly closer than what (x, y)
  // holds; false for a pixel off the canvas. (x, y) are canvas coordinates, mapped
  // to the buffer exactly as PutPixel maps them to the image.
  bool TestAndSet(int x, int y, double depth);

  // What the buffer holds at (x, y), which must be on the canvas.
  double At(int x, int y) const;

 private:
  DepthValue value_;
  CanvasGrid<double> depths_;
};

// "Depth Buffering": an attribute of a triangle's vertices interpolated along its
// edges, as x is in Listing 7-1 and h in Listing 8-1. y0 <= y1 <= y2; returns the
// values on the long side P0-P2 and on the two short sides P0-P1-P2 joined (the
// value at y1 once), one per row from y0 to y2.
std::pair<std::vector<double>, std::vector<double>> EdgeInterpolate(int y0, double v0, int y1,
                                                                    double v1, int y2, double v2);

// Listing 7-1 with a depth test before every PutPixel. z0, z1, z2 are the camera-space
// depths of the points that P0, P1, P2 are projections of; the buffer's DepthOf
// value is interpolated along the edges and across each row, like h in Listing 8-1.
void DrawFilledTriangle(Point P0, Point P1, Point P2, double z0, double z1, double z2,
                        const Color& color, Canvas& canvas, DepthBuffer& depth_buffer);
