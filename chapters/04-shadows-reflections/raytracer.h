// Chapter 4, "Shadows and Reflections": the scene, and the functions of the chapter
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
  double specular = -1;   // "Specular Reflection": the shininess exponent s; -1 means matte
  double reflective = 0;  // "Mirrors and Reflection": 0 not at all .. 1 a perfect mirror
};

// "Light Sources". All light is white, so a light is one intensity.
enum class LightType { kAmbient, kPoint, kDirectional };

struct Light {
  LightType type = LightType::kAmbient;
  double intensity = 0;
  Vec3 position{0, 0, 0};   // point lights
  Vec3 direction{0, 0, 0};  // directional lights: the direction towards the light, L itself
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
  std::vector<Light> lights;
  // t_min of shadow and reflection rays, so that a surface point does not find
  // itself at t = 0 ("Rendering with Shadows"). 0 shows that "shadow acne".
  double epsilon = 0.001;
};

// "Canvas to Viewport": the point of the viewport that canvas pixel (x, y) looks
// through. It is also the ray direction D = V - O, since the camera is at O = 0.
Vec3 CanvasToViewport(double x, double y, const Canvas& canvas, const Viewport& viewport);

// "Ray Meets Sphere": the two solutions t1 >= t2 of the quadratic
// t^2<D,D> + 2t<CO,D> + <CO,CO> - r^2 = 0, or (inf, inf) when the ray misses.
std::pair<double, double> IntersectRaySphere(const Vec3& O, const Vec3& D, const Sphere& sphere);

// Listing 4-1: the closest sphere hit by O + tD with t in [t_min, t_max] and its t,
// or (nullptr, inf). The search loop of chapter 3's TraceRay, taken out so that
// shadow rays can use it too.
std::pair<const Sphere*, double> ClosestIntersection(const Vec3& O, const Vec3& D, double t_min,
                                                     double t_max, const Scene& scene);

// "Rendering with Reflections": R mirrored about the unit normal N, 2N<N,R> - R.
Vec3 ReflectRay(const Vec3& R, const Vec3& N);

// Listing 4-3, "Rendering with Shadows": the light intensity at point P with unit
// normal N, seen from direction V (from P towards the camera), on a surface with
// specular exponent s. A light that another sphere hides from P adds nothing.
double ComputeLighting(const Vec3& P, const Vec3& N, const Vec3& V, double s, const Scene& scene);

// Listing 4-4: the closest sphere's lit colour, blended with what its mirror image
// shows (traced recursively, at most recursion_depth more bounces); or the background.
Color TraceRay(const Vec3& O, const Vec3& D, double t_min, double t_max, int recursion_depth,
               const Scene& scene);

// The main loop (Listing 2-2): one ray per canvas pixel, from the camera at the origin.
void RenderScene(const Scene& scene, int recursion_depth, Canvas& canvas);

// The book's advice: three bounces are enough ("Rendering with Reflections").
inline constexpr int kDefaultRecursionDepth = 3;
