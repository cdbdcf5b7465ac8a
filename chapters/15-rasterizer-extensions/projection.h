// Chapter 9, "Perspective Projection": from a point of the scene to a point of the
// canvas, under the book's names.
#pragma once

#include "cgfs/math.h"
#include "triangles.h"

using cgfs::Vec3;

// The viewport: a Vw x Vh window on the projection plane z = d, as in chapter 2.
struct Viewport {
  double width = 1;
  double height = 1;
  double distance = 1;  // d
};

// Listing 9-1: a viewport point (x, y) in canvas pixels, truncated toward zero.
Point ViewportToCanvas(double x, double y, const Canvas& canvas, const Viewport& viewport);

// Listing 9-1, "Finding P'": where the camera at the origin, looking along +Z, sees
// the scene point v on the canvas: (v.x * d / v.z, v.y * d / v.z) on the viewport.
// Precondition: v lies on or beyond the projection plane (v.z >= d). A point nearer
// the camera, or behind it, has no sensible projection (at v.z = 0 it divides by
// zero, behind the camera it lands upside down); chapter 11 clips geometry so that
// this never happens. Every scene of chapters 9 and 10 satisfies it.
Point ProjectVertex(const Vec3& v, const Canvas& canvas, const Viewport& viewport);
