#include "raytracer.h"

#include <cmath>

// Listing 2-3, "Canvas to Viewport": scale pixel units to viewport units; the viewport
// lies at z = d.
Vec3 CanvasToViewport(double x, double y, const Canvas& canvas, const Viewport& viewport) {
  return {x * viewport.width / canvas.Width(), y * viewport.height / canvas.Height(),
          viewport.distance};
}

// Listing 2-5, "Ray Meets Sphere": put the ray P = O + tD into the sphere equation
// <P-C, P-C> = r^2 and solve the quadratic for t. D is not normalised, so a = <D,D> is kept.
std::pair<double, double> IntersectRaySphere(const Vec3& O, const Vec3& D, const Sphere& sphere) {
  const double r = sphere.radius;
  const Vec3 CO = O - sphere.center;

  const double a = glm::dot(D, D);
  const double b = 2 * glm::dot(CO, D);
  const double c = glm::dot(CO, CO) - r * r;

  const double discriminant = b * b - 4 * a * c;
  if (discriminant < 0) {
    return {cgfs::kInf, cgfs::kInf};
  }
  const double t1 = (-b + std::sqrt(discriminant)) / (2 * a);
  const double t2 = (-b - std::sqrt(discriminant)) / (2 * a);
  return {t1, t2};
}

// Listing 2-4, "Rendering our First Spheres": keep the nearest root inside [t_min, t_max].
Color TraceRay(const Vec3& O, const Vec3& D, double t_min, double t_max, const Scene& scene) {
  double closest_t = cgfs::kInf;
  const Sphere* closest_sphere = nullptr;
  for (const Sphere& sphere : scene.spheres) {
    const auto [t1, t2] = IntersectRaySphere(O, D, sphere);
    if (t_min <= t1 && t1 <= t_max && t1 < closest_t) {
      closest_t = t1;
      closest_sphere = &sphere;
    }
    if (t_min <= t2 && t2 <= t_max && t2 < closest_t) {
      closest_t = t2;
      closest_sphere = &sphere;
    }
  }
  if (closest_sphere == nullptr) {
    return scene.background_color;
  }
  return closest_sphere->color;
}

// Listing 2-2. t_min = 1 keeps only what lies beyond the projection plane.
// The loops are half-open so that a Cw x Ch canvas gets exactly Cw x Ch rays.
void RenderScene(const Scene& scene, Canvas& canvas) {
  const Vec3 O{0, 0, 0};
  const int Cw = canvas.Width();
  const int Ch = canvas.Height();
  for (int x = -Cw / 2; x < Cw / 2; ++x) {
    for (int y = -Ch / 2; y < Ch / 2; ++y) {
      const Vec3 D = CanvasToViewport(x, y, canvas, scene.viewport);
      const Color color = TraceRay(O, D, 1, cgfs::kInf, scene);
      canvas.PutPixel(x, y, color);
    }
  }
}
