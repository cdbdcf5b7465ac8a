// A ray tracer's render loop seen through the canvas: every pixel painted, with one
// PutPixel each (one ray each, as the book's RenderScene puts one pixel per ray), and none
// off the canvas: half-open loops, x from -Cw/2 to Cw/2 - 1. The book's inclusive loops,
// -Cw/2 to Cw/2, trace (Cw + 1) x (Ch + 1) rays, whose extra pixels PutPixel drops, so
// only a count sees them.
#pragma once

#include <algorithm>
#include <functional>

#include <catch2/catch.hpp>

#include "cgfs/canvas.h"
#include "cgfs/tally.h"
#include "printing.h"

namespace cgfs::test {

// `render` draws a scene whose every ray misses (its background black) on a 40 x 30
// canvas, white before: not square, so x and y each run over their own side.
inline void CheckPaintsEveryPixelOnce(const std::function<void(Canvas&)>& render) {
  Canvas canvas(40, 30, kWhite);
  const Tallying put(kPixelsPut, 40, 30);
  render(canvas);
  CHECK_THAT(canvas.GetImage(), IsSameImageAs(Image(40, 30, Rgb8{0, 0, 0})));
  INFO("PutPixel calls: " << put.Total() << ", for " << 40 * 30
                          << " pixels (a loop over -Cw/2 to Cw/2 "
                             "inclusive makes "
                          << 41 * 31 << ")");
  CHECK(put.Total() == 40 * 30);
  CHECK(std::all_of(put.PerPixel().begin(), put.PerPixel().end(), [](long n) { return n == 1; }));
}

}  // namespace cgfs::test
