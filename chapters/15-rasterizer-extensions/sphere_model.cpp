#include "sphere_model.h"

#include <algorithm>
#include <cmath>
#include <numbers>

Model GenerateSphere(int divs, const Color& color) {
  Model sphere;
  const double delta_angle = 2 * std::numbers::pi / divs;
  for (int d = 0; d <= divs; ++d) {
    const double y = (2.0 / divs) * (d - divs / 2.0);
    const double radius = std::sqrt(std::max(0.0, 1 - y * y));
    for (int i = 0; i < divs; ++i) {
      sphere.vertices.push_back(
          {radius * std::cos(i * delta_angle), y, radius * std::sin(i * delta_angle)});
    }
  }
  // Two triangles between rings d and d + 1 for each i; the last i joins the first,
  // so there is no seam.
  for (int d = 0; d < divs; ++d) {
    for (int i = 0; i < divs; ++i) {
      const int i0 = d * divs + i;
      const int i1 = (d + 1) * divs + (i + 1) % divs;
      const int i2 = d * divs + (i + 1) % divs;
      for (const std::array<int, 3>& v : {std::array{i0, i1, i2}, std::array{i0, i0 + divs, i1}}) {
        sphere.triangles.push_back(
            {v, color, {sphere.vertices[v[0]], sphere.vertices[v[1]], sphere.vertices[v[2]]}});
      }
    }
  }
  return sphere;
}
