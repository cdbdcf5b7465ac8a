// Chapter 12, "Back Face Culling" and "Classifying Triangles", under the book's names.
#pragma once

#include "scene.h"

// "Classifying Triangles": N = (B - A) x (C - A) points out of a model whose
// triangles are listed clockwise as seen from outside, and V = camera - A points
// from the triangle to the camera. <N, V> <= 0 is back-facing; edge-on (= 0) counts
// as back-facing, so degenerate triangles are dropped too. A, B, C in the
// triangle's own order: sorting them (by y, to draw them) would flip N.
bool IsBackFacing(const Vec3& A, const Vec3& B, const Vec3& C, const Vec3& camera);

// Listing 12-1: removes every back-facing triangle of the object. Valid for closed
// models only, where the front faces cover the back faces; an open model must be
// drawn without it. Run after clipping (which keeps each triangle's winding) and
// before rasterising.
void CullBackFaces(Model& object, const Vec3& camera);
