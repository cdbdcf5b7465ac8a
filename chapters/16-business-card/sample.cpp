#include "sample.h"

#include <cmath>

#include <glm/geometric.hpp>

#include "trace.h"

CardColor SkyColor(const glm::dvec3& d) {
  return CardColor(0.7, 0.6, 1.0) * std::pow(1 - d.z, 4);
}

CardColor FloorTile(const glm::dvec3& h) {
  const glm::dvec3 scaled = h * 0.2;
  // The card's (int)(ceil(x) + ceil(y)) & 1: the parity of the sum, negative sums
  // included (−3 is odd). Taken on the double itself, without the card's conversion to
  // int, which is undefined for a point as far away as a moved view can reach.
  const double sum = std::ceil(scaled.x) + std::ceil(scaled.y);
  return std::fmod(sum, 2) != 0 ? CardColor(3, 1, 1) : CardColor(3, 3, 3);
}

CardColor Sample(const glm::dvec3& o, const glm::dvec3& d, Random& random, bool bounded,
                 int reflections) {
  double t = 0;
  glm::dvec3 n(0, 0, 1);
  const HitType m = Trace(o, d, t, n, bounded);
  if (m == HitType::Sky) {
    return SkyColor(d);
  }

  const glm::dvec3 h = o + d * t;  // the hit point
  // Towards a random point of the light (x first, then y: the card leaves the order
  // to the compiler).
  const double light_x = kLightX + random.Rand();
  const double light_y = kLightY + random.Rand();
  const glm::dvec3 l = glm::normalize(glm::dvec3(light_x, light_y, kLightZ) + h * -1.0);
  // The mirror direction: chapter 4's ReflectRay for the ray back towards the eye, −d,
  // which is d − 2⟨n, d⟩n.
  const glm::dvec3 r = d + n * (glm::dot(n, d) * -2);

  // Lambert's cosine, 0 if the surface faces away from the light or anything is in
  // the way. The shadow ray overwrites t and n, which are not used afterwards.
  double b = glm::dot(l, n);
  if (b < 0 || Trace(h, l, t, n, bounded) != HitType::Sky) {
    b = 0;
  }
  // Phong's highlight with exponent 99, only where the light reaches.
  const double p = std::pow(glm::dot(l, r) * (b > 0 ? 1.0 : 0.0), 99);

  if (m == HitType::Floor) {
    return FloorTile(h) * (b * 0.2 + 0.1);
  }
  const CardColor highlight(p, p, p);
  if (reflections == kMaxReflections) {
    return highlight;
  }
  return highlight + Sample(h, r, random, bounded, reflections + 1) * 0.5;
}
