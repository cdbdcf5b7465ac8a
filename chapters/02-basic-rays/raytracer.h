// Chapter 2, "Basic Ray Tracing": the scene, and the functions of the chapter
// under the book's names. Where the book reads a global (the canvas size, the
// viewport, the scene), the function takes it as a last parameter.
#pragma once

#include <utility>
#include <vector>

#include "cgfs/canvas.h"
#include "cgfs/color.h"
#include "cgfs/math.h"

using cgfs::Canvas;
using cgfs::Color;
using cgfs::Vec3;

struct Sphere {
  Vec3 center{0, 0, 0};
  double radius = 1;
  Color color{0, 0, 0};
};

// The viewport is a Vw x Vh window on the plane z = d ("Canvas to Viewport").
struct Viewport {
  double width = 1;
  double height = 1;
  double distance = 1;  // d, the projection plane
};

struct Scene {
  Viewport viewport;
  Color background_color = cgfs::kWhite;
  std::vector<Sphere> spheres;
};

// "Canvas to Viewport": the point of the viewport that canvas pixel (x, y) looks
// through. It is also the ray direction D = V - O, since the camera is at O = 0.
Vec3 CanvasToViewport(double x, double y, const Canvas& canvas, const Viewport& viewport);

// "Ray Meets Sphere": the two solutions t1 >= t2 of the quadratic
// t^2<D,D> + 2t<CO,D> + <CO,CO> - r^2 = 0, or (inf, inf) when the ray misses.
std::pair<double, double> IntersectRaySphere(const Vec3& O, const Vec3& D, const Sphere& sphere);

// "Rendering our First Spheres": the colour of the closest sphere hit with t in
// [t_min, t_max], or the background colour.
Color TraceRay(const Vec3& O, const Vec3& D, double t_min, double t_max, const Scene& scene);

// The main loop (Listing 2-2): one ray per canvas pixel, from the camera at the origin.
void RenderScene(const Scene& scene, Canvas& canvas);
