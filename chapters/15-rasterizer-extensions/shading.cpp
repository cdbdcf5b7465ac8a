#include "shading.h"

#include "normal_mapping.h"

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

// The change per pixel, across (x) and up (y) the canvas, of an attribute that is
// linear on the canvas, from its values at the triangle's three projected corners.
glm::dvec2 ScreenGradient(const std::array<Point, 3>& p, const std::array<double, 3>& a) {
  const double x1 = p[1].x - p[0].x;
  const double y1 = p[1].y - p[0].y;
  const double x2 = p[2].x - p[0].x;
  const double y2 = p[2].y - p[0].y;
  const double det = x1 * y2 - x2 * y1;
  if (det == 0) {
    return {0, 0};  // a triangle seen edge-on covers no area
  }
  const double a1 = a[1] - a[0];
  const double a2 = a[2] - a[0];
  return {(a1 * y2 - a2 * y1) / det, (x1 * a2 - x2 * a1) / det};
}

}  // namespace

double TexelsPerPixel(const glm::dvec2& duv_dx, const glm::dvec2& duv_dy, const Texture& texture) {
  const glm::dvec2 size(texture.width, texture.height);
  return std::max(glm::length(duv_dx * size), glm::length(duv_dy * size));
}

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
                   DepthBuffer& depth_buffer, const MipmappedTexture* texture,
                   const Texture* normal_map, double reflective) {
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
  // Chapter 14: u and v, or u/z and v/z, which are linear on the canvas.
  const bool perspective_correct =
      lighting.shading.texturing.interpolation == TextureInterpolation::kPerspectiveCorrect;
  const auto texture_u = [&](int i) {
    return perspective_correct ? corners[i].uv.x / corners[i].position.z : corners[i].uv.x;
  };
  const auto texture_v = [&](int i) {
    return perspective_correct ? corners[i].uv.y / corners[i].position.z : corners[i].uv.y;
  };
  const bool needs_uv = texture || normal_map;
  const auto [tu02, tu012] = edges(texture_u);
  const auto [tv02, tv012] = edges(texture_v);
  // How they, and 1/z, change per pixel across the canvas, for TexelsPerPixel.
  const std::array<Point, 3> points = {corners[0].projected, corners[1].projected,
                                       corners[2].projected};
  const glm::dvec2 tu_gradient = ScreenGradient(points, {texture_u(0), texture_u(1), texture_u(2)});
  const glm::dvec2 tv_gradient = ScreenGradient(points, {texture_v(0), texture_v(1), texture_v(2)});
  const glm::dvec2 iz_gradient = ScreenGradient(
      points, {1 / corners[0].position.z, 1 / corners[1].position.z, 1 / corners[2].position.z});

  // Chapter 15, "Normal Mapping": the directions on the triangle in which u and v grow.
  const TangentBasis tangents =
      ComputeTangentBasis({corners[0].position, corners[1].position, corners[2].position},
                          {corners[0].uv, corners[1].uv, corners[2].uv});
  // "Shadow Mapping": how much of each light reaches the pixel's point.
  std::vector<double> visibility(lighting.shadow_maps.empty() ? 0 : lighting.lights.size(), 1.0);
  // "Environment Mapping": a reflective surface's own colour counts 1 - reflective in
  // every pass; the reflection is added once, in the first.
  const bool mirrors = lighting.environment && reflective > 0 && model == ShadingModel::kPhong;
  const bool reflects = mirrors && lighting.pass.first;

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
    std::vector<double> tu_segment, tv_segment;
    if (needs_uv) {
      tu_segment = across(tu02, tu012);
      tv_segment = across(tv02, tv012);
    }
    std::vector<double> nx_segment, ny_segment, nz_segment;
    if (model == ShadingModel::kPhong) {
      nx_segment = across(nx02, nx012);
      ny_segment = across(ny02, ny012);
      nz_segment = across(nz02, nz012);
    }
    for (int x = x_l; x <= x_r; ++x) {
      const std::size_t i = static_cast<std::size_t>(x - x_l);
      if (!PassDepthTest(lighting.pass, depth_buffer, x, y_row, iz_segment[i])) {
        continue;
      }
      // Perspective-correct: u = (u/z) / (1/z); affine: u itself.
      const double iz = perspective_correct ? iz_segment[i] : 1.0;
      const double u = needs_uv ? tu_segment[i] / iz : 0.0;
      const double v = needs_uv ? tv_segment[i] / iz : 0.0;
      double intensity = flat;
      Color reflected(0, 0, 0);
      if (model == ShadingModel::kGouraud) {
        intensity = i_segment[i];
      } else if (model == ShadingModel::kPhong) {
        // The interpolated normal is shorter than 1 between the corners: normalise it.
        Vec3 N = glm::normalize(Vec3(nx_segment[i], ny_segment[i], nz_segment[i]));
        const Vec3 P = UnProjectVertex(x, y_row, iz_segment[i], canvas, viewport);
        if (normal_map) {
          const Color texel =
              GetTexel(*normal_map, u * normal_map->width - 0.5, v * normal_map->height - 0.5);
          N = ApplyNormalMap(DecodeNormal(texel), tangents, N);
        }
        if (!visibility.empty()) {
          const Vec3 P_world = cgfs::ToCartesian(lighting.camera_to_world * glm::dvec4(P, 1.0));
          const Vec3 N_world = Vec3(lighting.camera_to_world * glm::dvec4(N, 0.0));
          for (std::size_t light = 0; light < visibility.size(); ++light) {
            const ShadowMap* shadow_map = lighting.shadow_maps[light];
            visibility[light] =
                shadow_map ? LightVisibility(*shadow_map, P_world, N_world, lighting.shadow_mapping)
                           : 1.0;
          }
        }
        intensity = ComputeLighting(P, N, -P, specular, lighting.lights, lighting.shading.terms,
                                    visibility);
        if (reflects) {
          // Chapter 4's reflected ray, R = 2N<N, V> - V, turned into world space.
          const Vec3 R = ReflectRay(-P, N);
          reflected = SampleCubeMap(*lighting.environment,
                                    Vec3(lighting.camera_to_world * glm::dvec4(R, 0.0)));
        }
      }
      Color base = color;
      if (texture) {
        // The change of u and v per pixel: by the quotient rule when perspective-
        // correct; affine, u itself changes at the same rate everywhere.
        const glm::dvec2 du =
            perspective_correct ? (tu_gradient - u * iz_gradient) / iz : tu_gradient;
        const glm::dvec2 dv =
            perspective_correct ? (tv_gradient - v * iz_gradient) / iz : tv_gradient;
        const double rho = TexelsPerPixel({du.x, dv.x}, {du.y, dv.y}, texture->levels.front());
        base = SampleTexture(*texture, u, v, rho, lighting.shading.texturing.filter);
      }
      Color pixel = base * intensity;
      if (mirrors) {
        pixel = pixel * (1 - reflective) + reflected * reflective;
      }
      PassWrite(lighting.pass, canvas, x, y_row, pixel);
    }
  }
}
