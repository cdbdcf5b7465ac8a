// Chapter 6, "Lines": the functions of the chapter under the book's names. Where
// the book draws on a global canvas, the function takes it as a last parameter.
#pragma once

#include <string>
#include <vector>

#include "cgfs/canvas.h"
#include "cgfs/color.h"
#include "cgfs/figure.h"

using cgfs::Canvas;
using cgfs::Color;

// A point on the canvas, in pixels (origin at the centre, y up).
struct Point {
  int x = 0;
  int y = 0;
  friend bool operator==(const Point&, const Point&) = default;
};

// "Linear Interpolation": the values d = f(i) of the linear function with
// f(i0) = d0 and f(i1) = d1, for every integer i from i0 to i1 (the value for i is
// at index i - i0). [d0] when i0 == i1, and nothing when i0 > i1.
std::vector<double> Interpolate(int i0, double d0, int i1, double d1);

// Listing 6-2: a segment from P0 to P1 of any slope, in either direction; a single
// pixel when P0 == P1.
void DrawLine(Point P0, Point P1, const Color& color, Canvas& canvas);

// The chapter's earlier versions of DrawLine, each replaced for a reason the
// chapter explains (draw_line_drafts.cpp). Kept so a reader can see what each draws.
enum class DrawLineDraft {
  kSlopeIntercept,  // y = ax + b, left to right only
  kIncremental,     // y += a per step, left to right only
  kLeftToRight,     // swaps the end points first: any direction, but only y = f(x)
  kXOfY,            // the same with x and y swapped: fine for steep lines only
  kBothCases,       // Listing 6-1: picks y = f(x) or x = f(y)
};
void DrawLineDraftVersion(DrawLineDraft version, Point P0, Point P1, const Color& color,
                          Canvas& canvas);
// "slope-intercept", "incremental", ... and back; false for an unknown name.
std::string DraftName(DrawLineDraft version);
bool DraftFromName(const std::string& name, DrawLineDraft* version);
std::vector<DrawLineDraft> AllDrafts();

// Every figure this chapter draws, and one figure per draft asked for on the
// command line (--draw-line).
std::vector<cgfs::Figure> Figures(const std::vector<DrawLineDraft>& drafts = {});
