#include "draw_line_drafts.h"

#include <cmath>
#include <cstdlib>
#include <utility>

namespace {

// The drafts compute y (or x) in floating point and truncate it. A vertical line
// makes x1 - x0 = 0, and the book's division then gives inf or NaN, which has no
// pixel (in C++ converting it to int is undefined): such points are skipped, as a
// JavaScript canvas would skip them.
void PutPixelAt(double x, double y, const Color& color, Canvas& canvas) {
  if (std::isfinite(x) && std::isfinite(y) && std::abs(x) < 1e9 && std::abs(y) < 1e9) {
    canvas.PutPixel(static_cast<int>(x), static_cast<int>(y), color);
  }
}

}  // namespace

// First version.
void DrawLineSlopeIntercept(Point P0, Point P1, const Color& color, Canvas& canvas) {
  const double a = static_cast<double>(P1.y - P0.y) / (P1.x - P0.x);
  const double b = P0.y - a * P0.x;
  for (int x = P0.x; x <= P1.x; ++x) {
    const double y = a * x + b;
    PutPixelAt(x, y, color, canvas);
  }
}

// Second version.
void DrawLineIncremental(Point P0, Point P1, const Color& color, Canvas& canvas) {
  const double a = static_cast<double>(P1.y - P0.y) / (P1.x - P0.x);
  double y = P0.y;
  for (int x = P0.x; x <= P1.x; ++x) {
    PutPixelAt(x, y, color, canvas);
    y = y + a;
  }
}

// Third version.
void DrawLineLeftToRight(Point P0, Point P1, const Color& color, Canvas& canvas) {
  if (P0.x > P1.x) {
    std::swap(P0, P1);
  }
  const double a = static_cast<double>(P1.y - P0.y) / (P1.x - P0.x);
  double y = P0.y;
  for (int x = P0.x; x <= P1.x; ++x) {
    PutPixelAt(x, y, color, canvas);
    y = y + a;
  }
}

// The same with x and y swapped. Good for (0,0)-(50,100), gaps for (0,0)-(100,50).
void DrawLineXOfY(Point P0, Point P1, const Color& color, Canvas& canvas) {
  if (P0.y > P1.y) {
    std::swap(P0, P1);
  }
  const double a = static_cast<double>(P1.x - P0.x) / (P1.y - P0.y);
  double x = P0.x;
  for (int y = P0.y; y <= P1.y; ++y) {
    PutPixelAt(x, y, color, canvas);
    x = x + a;
  }
}

// Listing 6-1.
void DrawLineBothCases(Point P0, Point P1, const Color& color, Canvas& canvas) {
  const int dx = P1.x - P0.x;
  const int dy = P1.y - P0.y;
  if (std::abs(dx) > std::abs(dy)) {
    // The line is horizontal-ish. Make sure x0 < x1.
    if (P0.x > P1.x) {
      std::swap(P0, P1);
    }
    const double a = static_cast<double>(P1.y - P0.y) / (P1.x - P0.x);
    double y = P0.y;
    for (int x = P0.x; x <= P1.x; ++x) {
      PutPixelAt(x, y, color, canvas);
      y = y + a;
    }
  } else {
    // The line is vertical-ish. Make sure y0 < y1.
    if (P0.y > P1.y) {
      std::swap(P0, P1);
    }
    const double a = static_cast<double>(P1.x - P0.x) / (P1.y - P0.y);
    double x = P0.x;
    for (int y = P0.y; y <= P1.y; ++y) {
      PutPixelAt(x, y, color, canvas);
      x = x + a;
    }
  }
}
