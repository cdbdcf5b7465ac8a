// The versions of DrawLine that chapter 6 writes before Listing 6-2, in the order of
// "Drawing Lines" and "Drawing Lines with Any Slope". The book calls each of them
// DrawLine; here each has a name that says what it does. Each has a flaw the chapter
// goes on to fix, and each draws a figure of its own so that the flaw can be seen.
#pragma once

#include "lines.h"

// First version: y = ax + b for every x, assuming x0 < x1.
void DrawLineSlopeIntercept(Point P0, Point P1, const Color& color, Canvas& canvas);

// Second version: y(x + 1) = y(x) + a, one addition per pixel; still assumes x0 < x1.
void DrawLineIncremental(Point P0, Point P1, const Color& color, Canvas& canvas);

// Third version: swaps the end points so that x0 < x1. Any direction now, but one
// pixel per column, so steep lines get gaps (Figures 6-3 and 6-4).
void DrawLineLeftToRight(Point P0, Point P1, const Color& color, Canvas& canvas);

// The same with x and y swapped, x = f(y): good for steep lines only.
void DrawLineXOfY(Point P0, Point P1, const Color& color, Canvas& canvas);

// Listing 6-1: both, chosen by which of |dx| and |dy| is larger. It works, but the
// choice, the arithmetic and the drawing are tangled; Listing 6-2 pulls the
// arithmetic out into Interpolate.
void DrawLineBothCases(Point P0, Point P1, const Color& color, Canvas& canvas);
