// Chapter 7, "Filled Triangles": wireframe and filled triangles, under the book's names.
#pragma once

#include "lines.h"

// "Drawing Wireframe Triangles": the three sides, with DrawLine.
void DrawWireframeTriangle(Point P0, Point P1, Point P2, const Color& color, Canvas& canvas);

// Listing 7-1: the triangle as a stack of horizontal segments, from the lowest
// vertex to the highest. The vertices may come in any order.
void DrawFilledTriangle(Point P0, Point P1, Point P2, const Color& color, Canvas& canvas);
