// The triangle walker: chapter 8's DrawShadedTriangle (Listing 8-1) for any values,
// not only h. Shading carries several values from a triangle's corners to its pixels
// (1/z for the depth test, a light level, a normal), each along the edges and then
// across each row, exactly as Listing 8-1 carries h.
#pragma once

#include <array>
#include <utility>

#include "lines.h"

// A corner of a triangle: where it lands on the canvas, and the values it carries.
// Values is a number, or anything that can be added, subtracted and scaled like one.
template <typename Values>
struct WalkerCorner {
  Point p;
  Values values;
};

// One edge of a triangle, from corner a to corner b, as a function of y: x and the
// values on row y. The same numbers Interpolate(a.y, ..., b.y, ...) gives for row y,
// d0 + slope * (y - y0), computed for one row at a time instead of kept in a list.
template <typename Values>
class WalkerEdge {
 public:
  WalkerEdge(const WalkerCorner<Values>& a, const WalkerCorner<Values>& b)
      : y0_(a.p.y), x0_(a.p.x), values0_(a.values), flat_(a.p.y == b.p.y) {
    if (!flat_) {
      const double rows = b.p.y - a.p.y;
      x_slope_ = (b.p.x - a.p.x) / rows;
      values_slope_ = (b.values - a.values) / rows;
    }
  }

  double X(int y) const { return flat_ ? x0_ : x0_ + x_slope_ * static_cast<double>(y - y0_); }
  Values At(int y) const {
    return flat_ ? values0_ : values0_ + values_slope_ * static_cast<double>(y - y0_);
  }

 private:
  int y0_;
  double x0_;
  Values values0_;
  bool flat_;
  double x_slope_ = 0;
  Values values_slope_{};
};

// Listings 7-1 and 8-1: the triangle drawn row by row from the lowest corner to the
// highest, each row from the left edge to the right edge (ends truncated toward zero),
// and visit(x, y, values) called for every pixel with the values interpolated there.
// The long side P0-P2 is on one side, the short sides P0-P1 and P1-P2 on the other;
// which is left is decided on the middle row, as in Listing 7-1.
template <typename Values, typename Visit>
void WalkTriangle(std::array<WalkerCorner<Values>, 3> c, Visit&& visit) {
  // Sort the corners so that y0 <= y1 <= y2; each keeps its values.
  if (c[1].p.y < c[0].p.y) {
    std::swap(c[1], c[0]);
  }
  if (c[2].p.y < c[0].p.y) {
    std::swap(c[2], c[0]);
  }
  if (c[2].p.y < c[1].p.y) {
    std::swap(c[2], c[1]);
  }
  const int y0 = c[0].p.y;
  const int y1 = c[1].p.y;
  const int y2 = c[2].p.y;
  const WalkerEdge<Values> long_side(c[0], c[2]);
  const WalkerEdge<Values> lower_short_side(c[0], c[1]);
  const WalkerEdge<Values> upper_short_side(c[1], c[2]);
  // The short sides joined: the value at y1 belongs to the upper one.
  const auto short_side = [&](int y) -> const WalkerEdge<Values>& {
    return y < y1 ? lower_short_side : upper_short_side;
  };
  const int middle = y0 + (y2 - y0 + 1) / 2;
  const bool long_side_is_left = long_side.X(middle) < short_side(middle).X(middle);

  for (int y = y0; y <= y2; ++y) {
    const WalkerEdge<Values>& left = long_side_is_left ? long_side : short_side(y);
    const WalkerEdge<Values>& right = long_side_is_left ? short_side(y) : long_side;
    const int x_l = static_cast<int>(left.X(y));
    const int x_r = static_cast<int>(right.X(y));
    // Across the row, as Interpolate(x_l, values_l, x_r, values_r) would give them.
    const Values values_l = left.At(y);
    const Values slope =
        x_r > x_l ? (right.At(y) - values_l) / static_cast<double>(x_r - x_l) : Values{};
    for (int x = x_l; x <= x_r; ++x) {
      visit(x, y, values_l + slope * static_cast<double>(x - x_l));
    }
  }
}
