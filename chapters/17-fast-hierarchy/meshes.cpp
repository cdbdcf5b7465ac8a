#include "meshes.h"

#include <cmath>
#include <numbers>
#include <random>

Random::Random(std::uint64_t seed) {
  std::mt19937_64 generator(seed);
  state_[0] = generator();
  state_[1] = generator();
}

// xorshift128+: fast, and its arithmetic is exact, so the same on every machine.
std::uint64_t Random::Bits() {
  std::uint64_t x = state_[0];
  const std::uint64_t y = state_[1];
  state_[0] = y;
  x ^= x << 23;
  state_[1] = x ^ y ^ (x >> 17) ^ (y >> 26);
  return state_[1] + y;
}

double Random::Next() {
  return static_cast<double>(Bits() >> 11) * 0x1.0p-53;  // 53 random bits
}

std::vector<Sphere> SphereField(int count, std::uint64_t seed) {
  const Color palette[] = {cgfs::kRed,    cgfs::kGreen,  cgfs::kBlue, {255, 255, 255},
                           {255, 160, 0}, cgfs::kPurple, cgfs::kCyan};
  const double radius = 0.3 * std::cbrt(100.0 / count);
  Random random(seed);
  std::vector<Sphere> spheres;
  spheres.reserve(count);
  for (int i = 0; i < count; ++i) {
    const double x = random.Between(-3, 3);
    const double y = random.Between(-0.9, 2.5);
    const double z = random.Between(5, 12);
    const Color color = palette[static_cast<int>(random.Next() * std::size(palette))];
    spheres.emplace_back(Vec3{x, y, z}, radius, color, 100);
  }
  return spheres;
}

std::vector<Triangle> TorusMesh(double R, double r, int around, int across, Color color) {
  auto point = [&](int i, int j) {
    const double u = 2 * std::numbers::pi * i / around;
    const double v = 2 * std::numbers::pi * j / across;
    const double ring = R + r * std::cos(v);
    return Vec3{ring * std::cos(u), r * std::sin(v), ring * std::sin(u)};
  };
  std::vector<Triangle> triangles;
  triangles.reserve(2 * static_cast<std::size_t>(around) * across);
  for (int i = 0; i < around; ++i) {
    for (int j = 0; j < across; ++j) {
      const Vec3 a = point(i, j);
      const Vec3 b = point(i + 1, j);
      const Vec3 c = point(i + 1, j + 1);
      const Vec3 d = point(i, j + 1);
      triangles.emplace_back(a, c, b, color, 50);
      triangles.emplace_back(a, d, c, color, 50);
    }
  }
  return triangles;
}
