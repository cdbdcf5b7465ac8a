// Chapter 15, "Stencil Shadows": the stencil buffer, one integer per pixel of the
// canvas that a pass can count with and that later passes can read to decide which
// pixels they may draw.
#pragma once

#include <vector>

#include "cgfs/canvas.h"

using cgfs::Canvas;

class StencilBuffer {
 public:
  // Every pixel 0.
  explicit StencilBuffer(const Canvas& canvas);

  // What (x, y) holds; 0 for a pixel off the canvas. Canvas coordinates, mapped as
  // PutPixel maps them.
  int At(int x, int y) const;

  // Adds `delta` to (x, y); pixels off the canvas are ignored.
  void Add(int x, int y, int delta);

  // Every pixel back to 0.
  void Clear();

 private:
  const Canvas* canvas_;
  std::vector<int> counts_;
};
