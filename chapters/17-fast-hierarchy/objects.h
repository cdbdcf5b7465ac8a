// "Supporting Other Primitives": TraceRay needs only two things from an object, the
// nearest t where a ray meets it and the normal there. Behind the Object interface
// are the chapter's spheres, its triangles, and the solids of constructive solid
// geometry (csg.h).
#pragma once

#include <cmath>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

#include "cgfs/color.h"
#include "cgfs/math.h"

using cgfs::Color;
using cgfs::Vec3;

// A ray O + tD, with what the "Caching Invariants" section computes once per ray
// instead of once per sphere: <D,D>, and whether O is the camera's position, where the
// <CO,CO> a prepared sphere cached holds. Only prepared spheres use them; the others
// compute every value where the book does.
struct Ray {
  Ray(const Vec3& origin, const Vec3& direction, bool starts_at_camera = false)
      : O(origin), D(direction), from_camera(starts_at_camera), D_dot_D(glm::dot(D, D)) {}
  Vec3 O;
  Vec3 D;
  bool from_camera;
  double D_dot_D;
};

class Object;

// Where a ray meets an object: its t, the primitive whose surface it is (for a CSG
// solid, one of its parts), and whether the surface is seen from the primitive's
// inside out, so that its normal must be turned around (a crater cut into a sphere).
struct Hit {
  double t = cgfs::kInf;
  const Object* primitive = nullptr;
  bool flip_normal = false;
  int object = -1;  // the scene object hit, by index (set by ClosestIntersection)
};

// An axis-aligned box, the bound the bounding-volume hierarchy uses (bvh.h).
struct Box {
  Vec3 min{cgfs::kInf, cgfs::kInf, cgfs::kInf};
  Vec3 max{-cgfs::kInf, -cgfs::kInf, -cgfs::kInf};
};
// The box around both (inline: the hierarchy's build takes millions of them).
inline Box Union(const Box& a, const Box& b) {
  return {glm::min(a.min, b.min), glm::max(a.max, b.max)};
}
Box Intersection(const Box& a, const Box& b);
// The box grown by a hair, so that rounding can never make a ray that hits the
// object miss its box.
Box Padded(const Box& box);

// What a surface looks like, whatever its shape.
struct Surface {
  Color color{0, 0, 0};
  double specular = -1;         // "Specular Reflection": the shininess exponent s; -1 means matte
  double reflective = 0;        // "Mirrors and Reflection": 0 not at all .. 1 a perfect mirror
  double transparency = 0;      // "Transparency": 0 opaque .. 1 nothing but what lies behind
  double refractive_index = 1;  // "Refraction": of the material inside the surface
};

class Object {
 public:
  Object() = default;
  explicit Object(const Surface& looks) : surface(looks) {}
  virtual ~Object() = default;

  // The nearest hit with t in [t_min, t_max]; t = inf when there is none.
  virtual Hit Intersect(const Ray& ray, double t_min, double t_max) const = 0;
  // The unit normal at P, a point on this primitive, pointing out of it.
  virtual Vec3 Normal(const Vec3& P) const = 0;
  // A box the object lies in.
  virtual Box Bounds() const = 0;
  // A copy with what does not change while the scene is drawn cached in it ("Caching
  // Invariants"); nullptr when there is nothing to cache, and the object serves as it
  // is. A copy, never the object itself: two scenes drawn at once from two cameras
  // may share their objects.
  virtual std::shared_ptr<Object> Prepared(const Vec3& /*camera_position*/) const {
    return nullptr;
  }

  // A CSG solid's parts keep their own surfaces; the solid's own is not used.
  Surface surface;
};

// A span of t along a ray where the ray is inside a solid: from `in` to `out`.
struct Span {
  Hit in;
  Hit out;
};

// An object with an inside, which constructive solid geometry can combine.
class Solid : public Object {
 public:
  using Object::Object;
  // The spans where O + tD is inside, sorted by t, for t over the whole line.
  virtual void Spans(const Ray& ray, std::vector<Span>& spans) const = 0;
  // The nearest boundary in [t_min, t_max] of the spans.
  Hit Intersect(const Ray& ray, double t_min, double t_max) const override;
};

// "Caching Invariants": what a sphere's test can compute once, r², and <CO,CO> for
// rays from the camera.
struct SphereCache {
  double radius_squared = 1;
  double camera_CO_dot_CO = 0;
};

class Sphere final : public Solid {
 public:
  Sphere(Vec3 C, double r, Color color, double specular = -1, double reflective = 0,
         double transparency = 0, double refractive_index = 1)
      : Solid({color, specular, reflective, transparency, refractive_index}),
        center(C),
        radius(r) {}

  Hit Intersect(const Ray& ray, double t_min, double t_max) const override;
  void Spans(const Ray& ray, std::vector<Span>& spans) const override;
  Vec3 Normal(const Vec3& P) const override;
  Box Bounds() const override;
  std::shared_ptr<Object> Prepared(const Vec3& camera_position) const override;

  // Both roots of the ray's quadratic, with the cached values if this copy has them.
  std::pair<double, double> Roots(const Ray& ray) const;

  Vec3 center{0, 0, 0};
  double radius = 1;
  // Set in the copies Prepared makes, which test rays with it.
  SphereCache cache;
  bool cached = false;
};

// The quadratic formula of Listing 2-5: t1 >= t2, or (inf, inf) without real roots.
inline std::pair<double, double> QuadraticRoots(double a, double b, double c) {
  const double discriminant = b * b - 4 * a * c;
  if (discriminant < 0) {
    return {cgfs::kInf, cgfs::kInf};
  }
  const double t1 = (-b + std::sqrt(discriminant)) / (2 * a);
  const double t2 = (-b - std::sqrt(discriminant)) / (2 * a);
  return {t1, t2};
}

// "Ray Meets Sphere": the two solutions t1 >= t2 of the quadratic
// t^2<D,D> + 2t<CO,D> + <CO,CO> - r^2 = 0, or (inf, inf) when the ray misses.
std::pair<double, double> IntersectRaySphere(const Vec3& O, const Vec3& D, const Sphere& sphere);

// The same, with the ray's cached <D,D> and the sphere's cached r² (and <CO,CO> for a
// ray from the camera): the same arithmetic on the same values, so the same roots.
// Inline: the bounding-volume hierarchy tests its spheres with it.
inline std::pair<double, double> IntersectRaySphere(const Ray& ray, const Vec3& center,
                                                    const SphereCache& cache) {
  const Vec3 CO = ray.O - center;

  const double a = ray.D_dot_D;
  const double b = 2 * glm::dot(CO, ray.D);
  const double CO_dot_CO = ray.from_camera ? cache.camera_CO_dot_CO : glm::dot(CO, CO);
  const double c = CO_dot_CO - cache.radius_squared;
  return QuadraticRoots(a, b, c);
}

// The nearer of the two roots inside [t_min, t_max], tested in the order chapter 4's
// ClosestIntersection tests them; inf when neither is.
inline double NearestRoot(const std::pair<double, double>& roots, double t_min, double t_max) {
  const auto [t1, t2] = roots;
  double t = cgfs::kInf;
  if (t_min <= t1 && t1 <= t_max) {
    t = t1;
  }
  if (t_min <= t2 && t2 <= t_max && t2 < t) {
    t = t2;
  }
  return t;
}

class Triangle final : public Object {
 public:
  Triangle(Vec3 a, Vec3 b, Vec3 c, Color color, double specular = -1, double reflective = 0);

  Hit Intersect(const Ray& ray, double t_min, double t_max) const override;
  Vec3 Normal(const Vec3& P) const override;
  Box Bounds() const override;

  Vec3 A, B, C;  // counter-clockwise seen from the side the normal points to
  Vec3 N;        // the plane's unit normal, (B - A) x (C - A) normalised
};

// "Triangles": the t where O + tD meets the triangle's plane <N,P> = <N,A>, if the
// point lies inside the triangle; inf for a miss or a ray parallel to the plane.
double IntersectRayTriangle(const Vec3& O, const Vec3& D, const Triangle& triangle);

// The same on a triangle's corners and normal, and only for a t in [t_min, t_max]: the
// point is not tested against the edges when the plane is met outside (the same
// answer, for less work). Inline: the bounding-volume hierarchy tests its triangles with
// it, on its own copies of them.
inline double IntersectRayTriangle(const Vec3& O, const Vec3& D, const Vec3& A, const Vec3& B,
                                   const Vec3& C, const Vec3& N, double t_min, double t_max) {
  const double N_dot_D = glm::dot(N, D);
  if (N_dot_D == 0) {
    return cgfs::kInf;  // parallel to the plane: no single point of contact
  }
  const double plane_D = -glm::dot(N, A);  // the plane is <N,P> + plane_D = 0
  const double t = -(glm::dot(N, O) + plane_D) / N_dot_D;
  if (!(t_min <= t && t <= t_max)) {
    return cgfs::kInf;
  }
  const Vec3 P = O + t * D;
  if (glm::dot(glm::cross(B - A, P - A), N) < 0 || glm::dot(glm::cross(C - B, P - B), N) < 0 ||
      glm::dot(glm::cross(A - C, P - C), N) < 0) {
    return cgfs::kInf;
  }
  return t;
}
