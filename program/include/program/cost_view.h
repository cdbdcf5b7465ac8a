// Work per pixel as a picture: a count for each pixel (box tests, pixels written, mip
// level...) drawn through one colour ramp, with the scale along the bottom edge.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "cgfs/canvas.h"
#include "cgfs/image.h"
#include "cgfs/tally.h"

namespace cgfs {

// Dave Green's "cubehelix" ramp (Bull. Astr. Soc. India 39, 2011, 289), with his
// defaults (start 0.5, rotations -1.5, hue 1, gamma 1): from black at 0 to white at 1
// through blue, green and red, its brightness rising all the way, so that it reads in
// grey as well as in colour.
Rgb8 CostRamp(double position);

// Where `count` falls on the ramp when `scale_max` is its top: ln(1 + count) /
// ln(1 + scale_max), clamped to [0, 1]. On a log scale, so that one ray's 10 000 tests
// and another's 20 both read.
double CostPosition(double count, double scale_max);

// The height of the scale strip DrawCost puts along the bottom of a canvas.
int CostStripHeight(int canvas_height);

// Draws `counts` (one per pixel, row by row from the top, canvas.Width() x
// canvas.Height() of them) over the whole canvas, then the scale: a strip
// CostStripHeight() high across the bottom, under a white line, that runs from 0 at
// the left to `scale_max` at the right. Up to kCostStepsMax it shows each whole count
// as a block of equal width; above, the ramp runs smoothly. Counts above scale_max
// are drawn as scale_max, and a negative count, which stands for nothing there to count
// (no texture on the pixel, say), as kCostNothing, a grey the ramp never takes.
inline constexpr cgfs::Count kCostStepsMax = 16;
inline constexpr Rgb8 kCostNothing{128, 128, 128};
void DrawCost(Canvas& canvas, const std::vector<cgfs::Count>& counts, cgfs::Count scale_max);

// What a cost view says of its counts: their total and the largest, as
// "13 414 717 in all, at most 292".
std::string CostTotals(const std::vector<cgfs::Count>& counts);

// A cost view's drawing, and what it said of the counts it last drew, for its figure's
// `measured` (program/figure.h). Copies share what was said.
class CostView {
 public:
  CostView() : said_(std::make_shared<std::string>()) {}
  void Draw(Canvas& canvas, const std::vector<cgfs::Count>& counts, cgfs::Count scale_max) const {
    DrawCost(canvas, counts, scale_max);
    *said_ = CostTotals(counts);
  }
  std::function<std::string()> Measured() const {
    return [said = said_] { return *said; };
  }

 private:
  std::shared_ptr<std::string> said_;
};

}  // namespace cgfs
