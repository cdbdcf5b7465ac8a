#include "refraction.h"

#include <cmath>

// Snell's law in vector form: with I the unit incoming direction, eta = n1/n2 and
// c = cos a1 = -<N,I>, the refracted direction is eta·I + (eta·c - cos a2)·N, where
// cos² a2 = 1 - eta²(1 - c²). When that is negative, sin a2 would exceed 1.
std::optional<Vec3> RefractRay(const Vec3& D, const Vec3& N, double n1, double n2) {
  const Vec3 I = D / glm::length(D);
  const double eta = n1 / n2;
  const double c = -glm::dot(N, I);
  const double k = 1 - eta * eta * (1 - c * c);
  if (k < 0) {
    return std::nullopt;
  }
  return eta * I + (eta * c - std::sqrt(k)) * N;
}
