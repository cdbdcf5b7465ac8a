// The versions of DrawLine that chapter 6 writes before Listing 6-2, in the order
// of "Drawing Lines" and "Drawing Lines with Any Slope". Each has a flaw the
// chapter goes on to fix; --draw-line renders what each one draws.
#include <cmath>
#include <cstdlib>
#include <utility>

#include "rasterizer.h"

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

// First version: y = ax + b for every x, assuming x0 < x1.
void DrawLineSlopeIntercept(Point P0, Point P1, const Color& color, Canvas& canvas) {
  const double a = static_cast<double>(P1.y - P0.y) / (P1.x - P0.x);
  const double b = P0.y - a * P0.x;
  for (int x = P0.x; x <= P1.x; ++x) {
    const double y = a * x + b;
    PutPixelAt(x, y, color, canvas);
  }
}

// Second version: y(x + 1) = y(x) + a, no multiplication per pixel; still x0 < x1.
void DrawLineIncremental(Point P0, Point P1, const Color& color, Canvas& canvas) {
  const double a = static_cast<double>(P1.y - P0.y) / (P1.x - P0.x);
  double y = P0.y;
  for (int x = P0.x; x <= P1.x; ++x) {
    PutPixelAt(x, y, color, canvas);
    y = y + a;
  }
}

// Third version: swap the end points so that x0 < x1. Any direction now, but one
// pixel per column: steep lines get gaps (Figures 6-3 and 6-4).
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

// The same with x and y swapped: x = f(y). Good for (0,0)-(50,100), gaps for
// (0,0)-(100,50).
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

// Listing 6-1: both versions, chosen by which of dx and dy is larger. It works,
// but the choice, the arithmetic and the drawing are tangled: Listing 6-2 pulls
// the arithmetic out into Interpolate.
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

}  // namespace

void DrawLineDraftVersion(DrawLineDraft version, Point P0, Point P1, const Color& color,
                          Canvas& canvas) {
  switch (version) {
    case DrawLineDraft::kSlopeIntercept:
      return DrawLineSlopeIntercept(P0, P1, color, canvas);
    case DrawLineDraft::kIncremental:
      return DrawLineIncremental(P0, P1, color, canvas);
    case DrawLineDraft::kLeftToRight:
      return DrawLineLeftToRight(P0, P1, color, canvas);
    case DrawLineDraft::kXOfY:
      return DrawLineXOfY(P0, P1, color, canvas);
    case DrawLineDraft::kBothCases:
      return DrawLineBothCases(P0, P1, color, canvas);
  }
}

std::vector<DrawLineDraft> AllDrafts() {
  return {DrawLineDraft::kSlopeIntercept, DrawLineDraft::kIncremental, DrawLineDraft::kLeftToRight,
          DrawLineDraft::kXOfY, DrawLineDraft::kBothCases};
}

std::string DraftName(DrawLineDraft version) {
  switch (version) {
    case DrawLineDraft::kSlopeIntercept:
      return "slope-intercept";
    case DrawLineDraft::kIncremental:
      return "incremental";
    case DrawLineDraft::kLeftToRight:
      return "left-to-right";
    case DrawLineDraft::kXOfY:
      return "x-of-y";
    case DrawLineDraft::kBothCases:
      return "both-cases";
  }
  return "";
}

bool DraftFromName(const std::string& name, DrawLineDraft* version) {
  for (const DrawLineDraft draft : AllDrafts()) {
    if (DraftName(draft) == name) {
      *version = draft;
      return true;
    }
  }
  return false;
}
