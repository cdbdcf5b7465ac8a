// "Parallelism": every primary ray is independent of the others and the scene is
// only read, so the canvas can be drawn by several threads at once. Not a thread
// per ray (starting one costs far more than tracing a ray): the canvas is cut into
// tiles, and a pool of workers, one per core, takes the next tile as each comes free.
#pragma once

#include <functional>

#include "cgfs/canvas.h"
#include "cgfs/tally.h"

// A rectangle of canvas coordinates: x in [x_begin, x_end), y in [y_begin, y_end).
struct Tile {
  int x_begin, x_end, y_begin, y_end;
};

inline constexpr int kTileSide = 16;

// Calls draw_tile once for every tile of a width x height canvas, from `threads`
// workers (1: all on this thread, in order). draw_tile must only write its own pixels.
void ForEachTile(int width, int height, int threads,
                 const std::function<void(const Tile&)>& draw_tile);

// Calls draw(x, y) once for every pixel of the canvas, tile by tile as above. While a
// pixel is drawn it is its thread's current pixel (cgfs::CurrentPixel), so that the
// work counted with cgfs::Tally (tally.h) lands on it. In the header, so that `draw`
// is inlined into the loops (a call per pixel would cost more than the counting).
template <typename Draw>
void ForEachPixel(const cgfs::Canvas& canvas, int threads, const Draw& draw) {
  ForEachTile(canvas.Width(), canvas.Height(), threads, [&](const Tile& tile) {
    for (int x = tile.x_begin; x < tile.x_end; ++x) {
      for (int y = tile.y_begin; y < tile.y_end; ++y) {
        const cgfs::CurrentPixel current(x, y);
        draw(x, y);
      }
    }
  });
}
