// Chapter 9, "Perspective Projection": the functions of the chapter under the book's names. Where
// the book draws on a global canvas, the function takes it as a last parameter.
#pragma once

#include <optional>
#include <vector>

#include "cgfs/canvas.h"
#include "cgfs/color.h"
#include "cgfs/figure.h"
#include "cgfs/math.h"

using cgfs::Canvas;
using cgfs::Color;
using cgfs::Vec3;

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

// "Drawing Wireframe Triangles": the three sides, with DrawLine.
void DrawWireframeTriangle(Point P0, Point P1, Point P2, const Color& color, Canvas& canvas);

// Listing 7-1: the triangle as a stack of horizontal segments, from the lowest
// vertex to the highest. The vertices may come in any order.
void DrawFilledTriangle(Point P0, Point P1, Point P2, const Color& color, Canvas& canvas);

// Listing 8-1: the filled triangle, its colour scaled by h, which is interpolated
// along the sides like x and then across each row.
void DrawShadedTriangle(Point P0, Point P1, Point P2, const Color& color, Canvas& canvas);

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
// Until chapter 11 clips against the near plane, a point in front of the
// projection plane (v.z < d, the camera's own plane and behind it included) has
// no place on the canvas: nothing is returned for it.
std::optional<Point> ProjectVertex(const Vec3& v, const Canvas& canvas, const Viewport& viewport);

// The eight corners of a box, named as in Listing 9-1: A, B, C, D around the front
// face and the same letters on the back face.
struct Cube {
  Vec3 vAf{}, vBf{}, vCf{}, vDf{};
  Vec3 vAb{}, vBb{}, vCb{}, vDb{};
};

// Listing 9-1: the twelve edges of the cube, projected and drawn with DrawLine:
// the front face blue, the back face red, the edges between them green. An edge
// with an end that cannot be projected is skipped.
void DrawCube(const Cube& cube, Canvas& canvas, const Viewport& viewport);

// The cube of the figure (the author's demo), and the one the book's listing
// prints, which mostly lies outside a 600x600 canvas.
enum class CubeVariant { kDemo, kBook };
Cube ChapterCube(CubeVariant variant);

// Every figure this chapter draws.
std::vector<cgfs::Figure> Figures(CubeVariant variant = CubeVariant::kDemo);
