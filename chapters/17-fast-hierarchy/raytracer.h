// Chapter 5, "Extending the Raytracer": the scene, and the functions of the chapter
// under the book's names. Where the book reads a global (the canvas size, the
// viewport, the scene), the function takes it as a last parameter.
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include "bvh.h"
#include "cgfs/canvas.h"
#include "cgfs/color.h"
#include "cgfs/math.h"
#include "cgfs/tally.h"
#include "cgfs/view.h"
#include "objects.h"
#include "optimizations.h"
#include "refraction.h"

using cgfs::Canvas;
using cgfs::Color;
using cgfs::Vec3;

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

// "Camera Position and Orientation": where the camera is, and the rotation that
// turns its view from looking along +Z (y up) to where it looks.
struct Camera {
  Vec3 position{0, 0, 0};
  glm::dmat3 rotation{1.0};  // multiplies column vectors: D = rotation * V
};

struct Scene {
  Viewport viewport;
  Camera camera;
  Color background_color = cgfs::kWhite;
  std::vector<std::shared_ptr<Object>> objects;  // spheres, triangles, CSG solids
  std::vector<Light> lights;
  // t_min of shadow and reflection rays, so that a surface point does not find
  // itself at t = 0 ("Rendering with Shadows"). 0 shows that "shadow acne".
  double epsilon = 0.001;

  // What PrepareScene sets: the optimisations the functions below use, and the
  // bounding-volume hierarchy when that is one of them.
  Optimizations optimizations;
  std::shared_ptr<const Bvh> bvh;

  template <typename Shape>
  void Add(Shape shape) {
    objects.push_back(std::make_shared<Shape>(std::move(shape)));
  }
};

// Caches what the optimisations need (each sphere's r² and <CO,CO> from the camera,
// the hierarchy) and records which ones are on. Once per scene, before drawing it.
// The objects that cache something are replaced by prepared copies: RenderScene
// prepares a copy of the scene it is given, and leaves that scene's objects as they
// were, so that two renders of one scene from two cameras can run at once.
void PrepareScene(Scene& scene, const Optimizations& optimizations);

// The ray O + tD as the intersection functions take it: with <D,D> computed once, and
// whether it starts at the scene's camera (for the spheres that cached <CO,CO>).
Ray MakeRay(const Vec3& O, const Vec3& D, const Scene& scene);

// "Canvas to Viewport": the point of the viewport that canvas pixel (x, y) looks
// through. It is also the ray direction D = V - O, since the camera is at O = 0.
Vec3 CanvasToViewport(double x, double y, const Canvas& canvas, const Viewport& viewport);

// Listing 4-1: the closest object hit by O + tD with t in [t_min, t_max]: its t, the
// primitive it is on, and the scene object's index (-1 and t = inf for none). On a
// tie in t the object that comes first in the scene wins, with or without the
// hierarchy.
Hit ClosestIntersection(const Vec3& O, const Vec3& D, double t_min, double t_max,
                        const Scene& scene);

// "Shadow Optimizations": whether anything lies on O + tD with t in [t_min, t_max],
// stopping at the first object found (sets `object` to its index, or -1).
bool AnyIntersection(const Vec3& O, const Vec3& D, double t_min, double t_max, const Scene& scene,
                     int& object);

// Is light `light_index` hidden from P (L from P towards it, t up to t_max)? With
// the shadow optimisations: the object that hid it last time on this thread is
// tried first, and the search stops at the first hit.
bool IsInShadow(const Vec3& P, const Vec3& L, double t_max, int light_index, const Scene& scene);

// "Rendering with Reflections": R mirrored about the unit normal N, 2N<N,R> - R.
Vec3 ReflectRay(const Vec3& R, const Vec3& N);

// Listing 4-3, "Rendering with Shadows": the light intensity at point P with unit
// normal N, seen from direction V (from P towards the camera), on a surface with
// specular exponent s. A light that another sphere hides from P adds nothing.
double ComputeLighting(const Vec3& P, const Vec3& N, const Vec3& V, double s, const Scene& scene);

// Listing 4-4: the closest object's lit colour, blended with what its mirror image
// shows and, for a transparent one, what is seen through it (traced recursively, at
// most recursion_depth more bounces); or the background. medium_index is the
// refractive index of the material the ray travels in ("Refraction"). Each ray it
// traces, the camera's and those it spawns, is counted (a cost view, cost.h).
inline constexpr cgfs::Counter kTracedRays{"rays traced"};
Color TraceRay(const Vec3& O, const Vec3& D, double t_min, double t_max, int recursion_depth,
               const Scene& scene, double medium_index = kAirIndex);

// The second half of TraceRay: the colour where O + tD hits (hit from ClosestIntersection).
// Subsampling calls it directly when it already knows what a ray hits.
Color ColorAtHit(const Vec3& O, const Vec3& D, const Hit& hit, int recursion_depth,
                 const Scene& scene, double medium_index = kAirIndex);

// The camera moved as --window or --view asks (cgfs::View): along its own axes, then
// turned to the left (yaw, about its up axis) and up (pitch, about its right axis).
Camera MovedCamera(const Camera& camera, const cgfs::View& view);

// Listing 5-1: the direction of the ray through canvas point (x, y), turned with
// the camera.
Vec3 CameraRayDirection(double x, double y, const Canvas& canvas, const Scene& scene);

// The main loop (Listing 5-1): one ray per canvas pixel, from the camera, drawn with
// the exact optimisations chosen (see optimizations.h; subsampling, which is not
// exact, is a main loop of its own, sampling.h).
void RenderScene(const Scene& scene, int recursion_depth, Canvas& canvas,
                 const Optimizations& optimizations);

// The book's advice: three bounces are enough ("Rendering with Reflections").
inline constexpr int kDefaultRecursionDepth = 3;
