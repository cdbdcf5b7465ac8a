#include "trace.h"

#include <cmath>

#include <glm/geometric.hpp>

#include "bound.h"
#include "letters.h"

namespace {

// The unit sphere around `centre`: |o + s·d − centre|² = 1 with |d| = 1 is
// s² + 2bs + c = 0, with p = o − centre, b = ⟨p, d⟩, c = ⟨p, p⟩ − 1 (chapter 2's
// quadratic with a = 1 and half of its b). Only the nearer root, s = −b − √(b² − c),
// is used: a ray that starts inside a sphere (none does) would pass through it.
// A hit nearer than t replaces t, n and m.
void TraceSphere(const glm::dvec3& centre, const glm::dvec3& o, const glm::dvec3& d, double& t,
                 glm::dvec3& n, HitType& m) {
  const glm::dvec3 p = o - centre;
  const double b = glm::dot(p, d);
  const double c = glm::dot(p, p) - 1;
  const double q = b * b - c;
  if (q > 0) {
    const double s = -b - std::sqrt(q);
    if (s < t && s > kMinDistance) {
      t = s;
      n = glm::normalize(p + d * t);
      m = HitType::Sphere;
    }
  }
}

}  // namespace

HitType Trace(const glm::dvec3& o, const glm::dvec3& d, double& t, glm::dvec3& n, bool bounded) {
  t = 1e9;
  HitType m = HitType::Sky;

  // The floor z = 0: o.z + p·d.z = 0. A ray parallel to it (d.z == 0) never meets
  // it; the card divides by zero there and relies on how infinities compare.
  if (d.z != 0) {
    const double p = -o.z / d.z;
    if (p > kMinDistance) {
      t = p;
      n = {0, 0, 1};
      m = HitType::Floor;
    }
  }

  const auto& spheres = LetterSpheres();
  if (!bounded) {
    for (const glm::dvec3& centre : spheres) {
      TraceSphere(centre, o, d, t, n, m);
    }
    return m;
  }
  // The same spheres in the same order, skipping the letters whose box the ray misses.
  for (const LetterBound& letter : LetterBounds()) {
    if (MayHit(letter.box, o, d, t)) {
      for (int i = letter.first; i < letter.first + letter.count; ++i) {
        TraceSphere(spheres[static_cast<std::size_t>(i)], o, d, t, n, m);
      }
    }
  }
  return m;
}
