#include "shading.h"

#include <stdexcept>
#include <utility>

Vec3 ComputeTriangleNormal(const Vec3& A, const Vec3& B, const Vec3& C) {
  return glm::normalize(glm::cross(B - A, C - A));
}

// "Phong Shading". The canvas point (x, y) is the viewport point (x Vw/Cw, y Vh/Ch)
// on the projection plane z = d; the scene point behind it at depth Z is that
// point scaled by Z/d.
Vec3 UnProjectVertex(int x, int y, double inv_z, const Canvas& canvas, const Viewport& viewport) {
  const double z = 1 / inv_z;
  const double vx = x * viewport.width / canvas.Width();
  const double vy = y * viewport.height / canvas.Height();
  return {vx * z / viewport.distance, vy * z / viewport.distance, z};
}

namespace {

// The normals the shading uses at the three corners, unit length.
std::array<Vec3, 3> CornerNormals(const std::array<ShadedCorner, 3>& corners, NormalSource source) {
  if (source == NormalSource::kTriangle) {
    const Vec3 N =
        ComputeTriangleNormal(corners[0].position, corners[1].position, corners[2].position);
    return {N, N, N};
  }
  return {glm::normalize(corners[0].normal), glm::normalize(corners[1].normal),
          glm::normalize(corners[2].normal)};
}

}  // namespace

// "Flat Shading": one point, one normal, one value. V = -P: in camera space the
// camera is at the origin, and V goes from the point towards it.
double FlatIllumination(const std::array<ShadedCorner, 3>& corners, double specular,
                        const Lighting& lighting) {
  const std::array<Vec3, 3> normals = CornerNormals(corners, lighting.shading.normals);
  const Vec3 centroid = (corners[0].position + corners[1].position + corners[2].position) / 3.0;
  const Vec3 normal = glm::normalize(normals[0] + normals[1] + normals[2]);
  return ComputeLighting(centroid, normal, -centroid, specular, lighting.lights,
                         lighting.shading.terms);
}

// Listing 7-1 and "Depth Buffering" again, with the attributes each shading model
// needs carried along the edges and across the rows like h in Listing 8-1: 1/z for
// the depth test (and for UnProjectVertex), the illumination for Gouraud, the three
// components of the normal for Phong.
void ShadeTriangle(const std::array<ShadedCorner, 3>& corners, const Color& color, double specular,
                   const Lighting& lighting, Canvas& canvas, const Viewport& viewport,
                   DepthBuffer& depth_buffer) {
  if (depth_buffer.Value() != DepthValue::kInverseZ) {
    throw std::invalid_argument("ShadeTriangle needs a 1/z depth buffer");
  }
  const ShadingModel model = lighting.shading.model;
  const std::array<Vec3, 3> normals = CornerNormals(corners, lighting.shading.normals);

  // The illumination at the corners (Gouraud) or of the whole triangle (flat).
  std::array<double, 3> illumination{};
  if (model == ShadingModel::kGouraud) {
    for (int k = 0; k < 3; ++k) {
      illumination[k] = ComputeLighting(corners[k].position, normals[k], -corners[k].position,
                                        specular, lighting.lights, lighting.shading.terms);
    }
  }
  const double flat =
      model == ShadingModel::kFlat ? FlatIllumination(corners, specular, lighting) : 0.0;

  // Sort the corners so that y0 <= y1 <= y2; each keeps its attributes.
  std::array<int, 3> k = {0, 1, 2};
  const auto y = [&](int i) { return corners[k[i]].projected.y; };
  if (y(1) < y(0)) {
    std::swap(k[1], k[0]);
  }
  if (y(2) < y(0)) {
    std::swap(k[2], k[0]);
  }
  if (y(2) < y(1)) {
    std::swap(k[2], k[1]);
  }
  const Point& P0 = corners[k[0]].projected;
  const Point& P1 = corners[k[1]].projected;
  const Point& P2 = corners[k[2]].projected;

  // An attribute of the corners along the edges: the long side, the short sides.
  const auto edges = [&](const auto& value) {
    return EdgeInterpolate(P0.y, value(k[0]), P1.y, value(k[1]), P2.y, value(k[2]));
  };
  const auto [x02, x012] =
      edges([&](int i) { return static_cast<double>(corners[i].projected.x); });
  const auto [iz02, iz012] = edges([&](int i) { return 1 / corners[i].position.z; });
  const auto [i02, i012] = edges([&](int i) { return illumination[i]; });
  const auto [nx02, nx012] = edges([&](int i) { return normals[i].x; });
  const auto [ny02, ny012] = edges([&](int i) { return normals[i].y; });
  const auto [nz02, nz012] = edges([&](int i) { return normals[i].z; });

  // Which side is left, by x on the middle row; every attribute follows.
  const std::size_t m = x012.size() / 2;
  const bool long_side_is_left = x02[m] < x012[m];
  const auto left = [&](const auto& a02, const auto& a012) -> const std::vector<double>& {
    return long_side_is_left ? a02 : a012;
  };
  const auto right = [&](const auto& a02, const auto& a012) -> const std::vector<double>& {
    return long_side_is_left ? a012 : a02;
  };

  for (int y_row = P0.y; y_row <= P2.y; ++y_row) {
    const std::size_t row = static_cast<std::size_t>(y_row - P0.y);
    const int x_l = static_cast<int>(left(x02, x012)[row]);
    const int x_r = static_cast<int>(right(x02, x012)[row]);
    // An attribute across the row, from x_l to x_r.
    const auto across = [&](const auto& a02, const auto& a012) {
      return Interpolate(x_l, left(a02, a012)[row], x_r, right(a02, a012)[row]);
    };
    const std::vector<double> iz_segment = across(iz02, iz012);
    const std::vector<double> i_segment =
        model == ShadingModel::kGouraud ? across(i02, i012) : std::vector<double>{};
    std::vector<double> nx_segment, ny_segment, nz_segment;
    if (model == ShadingModel::kPhong) {
      nx_segment = across(nx02, nx012);
      ny_segment = across(ny02, ny012);
      nz_segment = across(nz02, nz012);
    }
    for (int x = x_l; x <= x_r; ++x) {
      const std::size_t i = static_cast<std::size_t>(x - x_l);
      if (!depth_buffer.TestAndSet(x, y_row, iz_segment[i])) {
        continue;
      }
      double intensity = flat;
      if (model == ShadingModel::kGouraud) {
        intensity = i_segment[i];
      } else if (model == ShadingModel::kPhong) {
        // The interpolated normal is shorter than 1 between the corners: normalise it.
        const Vec3 N = glm::normalize(Vec3(nx_segment[i], ny_segment[i], nz_segment[i]));
        const Vec3 P = UnProjectVertex(x, y_row, iz_segment[i], canvas, viewport);
        intensity = ComputeLighting(P, N, -P, specular, lighting.lights, lighting.shading.terms);
      }
      canvas.PutPixel(x, y_row, color * intensity);
    }
  }
}
