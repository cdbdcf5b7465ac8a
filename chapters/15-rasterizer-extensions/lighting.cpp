#include "lighting.h"

#include <cmath>

// Chapter 3, Listings 3-1 and 3-2: ambient, plus each light's diffuse and specular
// reflection. As in chapter 3, the specular term is not guarded by <N, L> > 0.
double ComputeLighting(const Vec3& P, const Vec3& N, const Vec3& V, double s,
                       const std::vector<Light>& lights, const LightingTerms& terms,
                       std::span<const double> visibility) {
  double i = 0.0;
  for (std::size_t k = 0; k < lights.size(); ++k) {
    const Light& light = lights[k];
    if (light.type == LightType::kAmbient) {
      i += light.intensity;
      continue;
    }
    const double reaching = visibility.empty() ? 1.0 : visibility[k];
    if (reaching == 0) {
      continue;  // "Shadows": in the shadow of this light
    }
    const Vec3 L = light.type == LightType::kPoint ? light.position - P : light.direction;

    // "Diffuse Reflection": I * cos(angle between N and L); light from behind adds nothing.
    const double n_dot_l = glm::dot(N, L);
    if (terms.diffuse && n_dot_l > 0) {
      i += reaching * light.intensity * n_dot_l / (glm::length(N) * glm::length(L));
    }

    // "Specular Reflection": I * cos(angle between R and V)^s, with R the mirror
    // image of L about N.
    if (terms.specular && s != -1) {
      const Vec3 R = 2.0 * N * glm::dot(N, L) - L;
      const double r_dot_v = glm::dot(R, V);
      if (r_dot_v > 0) {
        i += reaching * light.intensity * std::pow(r_dot_v / (glm::length(R) * glm::length(V)), s);
      }
    }
  }
  return i;
}

std::vector<Light> TransformLights(const std::vector<Light>& lights, const glm::dmat4& M_camera) {
  std::vector<Light> transformed = lights;
  for (Light& light : transformed) {
    light.position = cgfs::ToCartesian(M_camera * glm::dvec4(light.position, 1.0));
    light.direction = Vec3(M_camera * glm::dvec4(light.direction, 0.0));
  }
  return transformed;
}
