// Chapter 8, "Shaded Triangles": a triangle whose colour is scaled by an intensity
// interpolated from its vertices, under the book's name.
#pragma once

#include "triangles.h"

// Listing 8-1: the filled triangle, its colour scaled by h, which is interpolated
// along the sides like x and then across each row.
void DrawShadedTriangle(Point P0, Point P1, Point P2, const Color& color, Canvas& canvas);
