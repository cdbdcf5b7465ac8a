// Chapter 6, "Lines": points on the canvas, Interpolate and the final DrawLine, under
// the book's names. Where the book draws on a global canvas, the function takes it
// as a last parameter.
#pragma once

#include <vector>

#include "cgfs/canvas.h"
#include "cgfs/color.h"

using cgfs::Canvas;
using cgfs::Color;

// A point on the canvas, in pixels (origin at the centre, y up), with the
// intensity h of the colour there ("Defining Our Problem": 0 black, 1 full colour).
struct Point {
  int x = 0;
  int y = 0;
  double h = 1;
  friend bool operator==(const Point&, const Point&) = default;
};

// "Linear Interpolation": the values d = f(i) of the linear function with
// f(i0) = d0 and f(i1) = d1, for every integer i from i0 to i1 (the value for i is
// at index i - i0). [d0] when i0 == i1, and nothing when i0 > i1.
std::vector<double> Interpolate(int i0, double d0, int i1, double d1);

// Listing 6-2: a segment from P0 to P1 of any slope, in either direction; a single
// pixel when P0 == P1.
void DrawLine(Point P0, Point P1, const Color& color, Canvas& canvas);
