// Scenes made by code rather than by hand: many spheres, many triangles.
#pragma once

#include <cstdint>
#include <vector>

#include "objects.h"

// A generator of numbers in [0, 1) from a seed, the same on every machine and
// compiler: std::mt19937_64's sequence is fixed by the C++ standard, and the
// conversion to double is ours (std::uniform_real_distribution's is not fixed).
class Random {
 public:
  explicit Random(std::uint64_t seed);
  double Next();
  double Between(double low, double high) { return low + (high - low) * Next(); }

 private:
  std::uint64_t state_[2];
  std::uint64_t Bits();
};

// `count` spheres placed at random (from `seed`) in the box x in [-3, 3],
// y in [-0.9, 2.5], z in [5, 12], all of one radius chosen so that the field looks
// about as full whatever the count: 0.3 * (100 / count)^(1/3).
std::vector<Sphere> SphereField(int count, std::uint64_t seed);

// A torus around the y axis, centred at the origin: `around` steps along the ring of
// radius R, `across` steps around the tube of radius r, two triangles per step,
// wound counter-clockwise seen from outside.
std::vector<Triangle> TorusMesh(double R, double r, int around, int across, Color color);
