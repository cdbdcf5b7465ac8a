// Chapter 15, "Stencil Shadows": the stencil buffer, one integer per pixel of the
// canvas that a pass can count with and that later passes can read to decide which
// pixels they may draw.
#pragma once

#include "canvas_grid.h"
#include "cgfs/tally.h"

// Each write to the stencil, counted at its pixel (a cost view).
inline constexpr cgfs::Counter kStencilWrites{"stencil writes"};

class StencilBuffer {
 public:
  // Every pixel 0.
  explicit StencilBuffer(const cgfs::Canvas& canvas) : counts_(canvas, 0) {}

  // What (x, y) holds; 0 for a pixel off the canvas.
  int At(int x, int y) const {
    const int* count = counts_.Find(x, y);
    return count ? *count : 0;
  }

  // Adds `delta` to (x, y); pixels off the canvas are ignored.
  void Add(int x, int y, int delta) {
    if (int* count = counts_.Find(x, y)) {
      *count += delta;
      cgfs::TallyAt(kStencilWrites, x, y);
    }
  }

  // Every pixel back to 0.
  void Clear() { counts_.Fill(0); }

 private:
  CanvasGrid<int> counts_;
};
