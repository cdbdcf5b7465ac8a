#include "ray_caster.h"

#include <algorithm>

#include <glm/geometric.hpp>

namespace cgfs::test {

namespace {

// Where O + tD crosses the ray's sphere, if it does between t_min and t_max.
bool MeetsBounds(const CastBounds& bounds, const glm::dvec3& O, const glm::dvec3& D, double t_min,
                 double t_max) {
  const glm::dvec3 CO = O - bounds.centre;
  const double a = glm::dot(D, D);
  const double b = 2 * glm::dot(CO, D);
  const double c = glm::dot(CO, CO) - bounds.radius * bounds.radius * 1.0001;
  const double discriminant = b * b - 4 * a * c;
  if (discriminant < 0) {
    return false;
  }
  const double root = std::sqrt(discriminant);
  return (-b + root) / (2 * a) > t_min && (-b - root) / (2 * a) < t_max;
}

}  // namespace

std::optional<double> MeetsTriangle(const CastTriangle& T, const glm::dvec3& O,
                                    const glm::dvec3& D) {
  const glm::dvec3 e1 = T.b - T.a;
  const glm::dvec3 e2 = T.c - T.a;
  const glm::dvec3 p = glm::cross(D, e2);
  const double det = glm::dot(e1, p);
  if (det == 0) {
    return std::nullopt;
  }
  const glm::dvec3 s = O - T.a;
  const double u = glm::dot(s, p) / det;
  if (u < 0 || u > 1) {
    return std::nullopt;
  }
  const glm::dvec3 q = glm::cross(s, e1);
  const double v = glm::dot(D, q) / det;
  if (v < 0 || u + v > 1) {
    return std::nullopt;
  }
  return glm::dot(e2, q) / det;
}

std::optional<CastHit> Cast(const CastScene& scene, const glm::dvec3& O, const glm::dvec3& D,
                            double t_min, double t_max, bool cull_back_faces) {
  std::optional<CastHit> closest;
  double t_best = t_max;
  for (const CastBounds& bounds : scene.instances) {
    if (!MeetsBounds(bounds, O, D, t_min, t_best)) {
      continue;
    }
    for (std::size_t k = bounds.first; k < bounds.last; ++k) {
      const CastTriangle& T = scene.triangles[k];
      const glm::dvec3 N = glm::cross(T.b - T.a, T.c - T.a);
      if (cull_back_faces && T.closed && glm::dot(N, D) >= 0) {
        continue;
      }
      const std::optional<double> t = MeetsTriangle(T, O, D);
      if (t && *t > t_min && *t < t_best) {
        t_best = *t;
        closest = CastHit{T.instance, T.triangle, *t, O + *t * D, glm::normalize(N)};
      }
    }
  }
  return closest;
}

bool LabelImage::Inside(int x, int y, int margin) const {
  const int here = At(x, y);
  for (int ny = std::max(-height / 2, y - margin); ny <= std::min(height / 2 - 1, y + margin);
       ++ny) {
    for (int nx = std::max(-width / 2, x - margin); nx <= std::min(width / 2 - 1, x + margin);
         ++nx) {
      if (At(nx, ny) != here) {
        return false;
      }
    }
  }
  return true;
}

LabelImage LabelsOf(const CastImage& cast, const std::function<int(const CastHit&)>& label) {
  LabelImage image{cast.width, cast.height, {}};
  image.labels.reserve(cast.hits.size());
  for (const CastHit& hit : cast.hits) {
    image.labels.push_back(label(hit));
  }
  return image;
}
CastImage CastCameraImage(const CastScene& scene, const CastCamera& camera, int width, int height) {
  CastImage image{width, height, {}};
  image.hits.reserve(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  for (int y = height / 2 - 1; y >= -height / 2; --y) {
    for (int x = -width / 2; x < width / 2; ++x) {
      const glm::dvec3 viewport_point(x * camera.viewport_width / width,
                                      y * camera.viewport_height / height, camera.distance);
      const glm::dvec3 D = camera.orientation * viewport_point;
      const std::optional<CastHit> hit =
          Cast(scene, camera.position, D, 1, std::numeric_limits<double>::infinity(), true);
      image.hits.push_back(hit ? *hit : CastHit{});
    }
  }
  return image;
}

bool LightBlocked(const CastScene& scene, const glm::dvec3& P, const glm::dvec3& light_position) {
  const glm::dvec3 start = P + 1e-6 * glm::normalize(light_position - P);
  return Cast(scene, start, light_position - start, 1e-9, 1, false).has_value();
}

bool DirectionalLightBlocked(const CastScene& scene, const glm::dvec3& P,
                             const glm::dvec3& light_direction) {
  const glm::dvec3 start = P + 1e-6 * glm::normalize(light_direction);
  return Cast(scene, start, light_direction, 1e-9, std::numeric_limits<double>::infinity(), false)
      .has_value();
}

}  // namespace cgfs::test
