#include "objects.h"

#include <algorithm>
#include <cmath>

Box Intersection(const Box& a, const Box& b) {
  return {glm::max(a.min, b.min), glm::min(a.max, b.max)};
}

Box Padded(const Box& box) {
  const Vec3 size = box.max - box.min;
  const double scale =
      std::max({size.x, size.y, size.z, glm::length(box.min), glm::length(box.max)});
  const Vec3 pad(1e-9 * scale + 1e-12);
  return {box.min - pad, box.max + pad};
}

Hit Solid::Intersect(const Ray& ray, double t_min, double t_max) const {
  // Kept by each thread from ray to ray, so that a test allocates nothing. Spans never
  // calls Intersect, so one vector a thread is enough.
  thread_local std::vector<Span> spans;
  spans.clear();
  Spans(ray, spans);
  for (const Span& span : spans) {
    for (const Hit& boundary : {span.in, span.out}) {
      if (t_min <= boundary.t && boundary.t <= t_max && boundary.t < cgfs::kInf) {
        return boundary;
      }
    }
  }
  return {};
}

// Listing 2-5, "Ray Meets Sphere": put the ray P = O + tD into the sphere equation
// <P-C, P-C> = r^2 and solve the quadratic for t. D is not normalised, so a = <D,D> is kept.
std::pair<double, double> IntersectRaySphere(const Vec3& O, const Vec3& D, const Sphere& sphere) {
  const double r = sphere.radius;
  const Vec3 CO = O - sphere.center;

  const double a = glm::dot(D, D);
  const double b = 2 * glm::dot(CO, D);
  const double c = glm::dot(CO, CO) - r * r;
  return QuadraticRoots(a, b, c);
}

std::pair<double, double> Sphere::Roots(const Ray& ray) const {
  return cached ? IntersectRaySphere(ray, center, cache) : IntersectRaySphere(ray.O, ray.D, *this);
}

Hit Sphere::Intersect(const Ray& ray, double t_min, double t_max) const {
  const double t = NearestRoot(Roots(ray), t_min, t_max);
  return t < cgfs::kInf ? Hit{t, this} : Hit{};
}

// "Constructive Solid Geometry": the ray is inside the sphere between its two roots.
void Sphere::Spans(const Ray& ray, std::vector<Span>& spans) const {
  const auto [t1, t2] = Roots(ray);
  if (t1 < cgfs::kInf) {
    spans.push_back({{t2, this}, {t1, this}});
  }
}

// "Sphere Normals": along CP.
Vec3 Sphere::Normal(const Vec3& P) const {
  const Vec3 N = P - center;
  return N / glm::length(N);
}

Box Sphere::Bounds() const {
  return Padded({center - Vec3(radius), center + Vec3(radius)});
}

std::shared_ptr<Object> Sphere::Prepared(const Vec3& camera_position) const {
  auto prepared = std::make_shared<Sphere>(*this);
  const Vec3 CO = camera_position - center;
  prepared->cache = {radius * radius, glm::dot(CO, CO)};
  prepared->cached = true;
  return prepared;
}

Triangle::Triangle(Vec3 a, Vec3 b, Vec3 c, Color color, double specular, double reflective)
    : Object(Surface{color, specular, reflective}), A(a), B(b), C(c) {
  N = glm::normalize(glm::cross(B - A, C - A));
}

// "Triangles": first the plane, then three sign tests. P is inside when it lies on
// the inner side of every edge, that is when each (edge x (P - edge start)) points
// the same way as N. Points on an edge count as inside.
double IntersectRayTriangle(const Vec3& O, const Vec3& D, const Triangle& triangle) {
  return IntersectRayTriangle(O, D, triangle.A, triangle.B, triangle.C, triangle.N, -cgfs::kInf,
                              cgfs::kInf);
}

Hit Triangle::Intersect(const Ray& ray, double t_min, double t_max) const {
  const double t = IntersectRayTriangle(ray.O, ray.D, A, B, C, N, t_min, t_max);
  if (t < cgfs::kInf) {
    return {t, this};
  }
  return {};
}

Vec3 Triangle::Normal(const Vec3& /*P*/) const {
  return N;
}

Box Triangle::Bounds() const {
  return Padded({glm::min(A, glm::min(B, C)), glm::max(A, glm::max(B, C))});
}
