#include "shading.h"

#include "triangle_walker.h"

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

Attributes operator+(const Attributes& a, const Attributes& b) {
  return {a.inv_z + b.inv_z, a.illumination + b.illumination, a.normal + b.normal};
}

Attributes operator-(const Attributes& a, const Attributes& b) {
  return {a.inv_z - b.inv_z, a.illumination - b.illumination, a.normal - b.normal};
}

Attributes operator*(const Attributes& a, double k) {
  return {a.inv_z * k, a.illumination * k, a.normal * k};
}

Attributes operator/(const Attributes& a, double k) {
  return {a.inv_z / k, a.illumination / k, a.normal / k};
}

std::array<Vec3, 3> CornerNormals(const std::array<ShadedCorner, 3>& corners, NormalSource source) {
  if (source == NormalSource::kTriangle) {
    const Vec3 N =
        ComputeTriangleNormal(corners[0].position, corners[1].position, corners[2].position);
    return {N, N, N};
  }
  return {glm::normalize(corners[0].normal), glm::normalize(corners[1].normal),
          glm::normalize(corners[2].normal)};
}

// "Flat Shading": one point, one normal, one value.
double FlatIllumination(const std::array<ShadedCorner, 3>& corners, double specular,
                        const Lighting& lighting) {
  const std::array<Vec3, 3> normals = CornerNormals(corners, lighting.shading.normals);
  const Vec3 centroid = (corners[0].position + corners[1].position + corners[2].position) / 3.0;
  const Vec3 normal = glm::normalize(normals[0] + normals[1] + normals[2]);
  return ComputeLighting(centroid, normal, -centroid, specular, lighting.lights,
                         lighting.shading.terms);
}

namespace {

// The corners as the walker takes them: where each lands, and its 1/z, illumination
// and normal.
std::array<WalkerCorner<Attributes>, 3> WalkerCorners(const std::array<ShadedCorner, 3>& corners,
                                                      const std::array<double, 3>& illumination,
                                                      const std::array<Vec3, 3>& normals) {
  std::array<WalkerCorner<Attributes>, 3> walker_corners;
  for (std::size_t k = 0; k < 3; ++k) {
    walker_corners[k] = {corners[k].projected,
                         {1 / corners[k].position.z, illumination[k], normals[k]}};
  }
  return walker_corners;
}

// Every pixel of the triangle that passes the depth test gets shade(x, y, attributes).
template <typename Shade>
void FillTriangle(const std::array<WalkerCorner<Attributes>, 3>& corners, Frame& frame,
                  const Shade& shade) {
  WalkTriangle(corners, [&](int x, int y, const Attributes& attributes) {
    if (frame.TestAndSet(x, y, attributes.inv_z)) {
      frame.Write(x, y, shade(x, y, attributes));
    }
  });
}

}  // namespace

void ShadeFlat(const std::array<ShadedCorner, 3>& corners, const Surface& surface,
               const Lighting& lighting, Frame& frame) {
  const Color color = surface.color * FlatIllumination(corners, surface.specular, lighting);
  FillTriangle(WalkerCorners(corners, {}, {}), frame,
               [&](int, int, const Attributes&) { return color; });
}

// "Gouraud Shading": the light at each corner, with that corner's normal, carried
// across the triangle like h in Listing 8-1.
void ShadeGouraud(const std::array<ShadedCorner, 3>& corners, const Surface& surface,
                  const Lighting& lighting, Frame& frame) {
  const std::array<Vec3, 3> normals = CornerNormals(corners, lighting.shading.normals);
  std::array<double, 3> illumination{};
  for (std::size_t k = 0; k < 3; ++k) {
    const Vec3& P = corners[k].position;
    illumination[k] = ComputeLighting(P, normals[k], -P, surface.specular, lighting.lights,
                                      lighting.shading.terms);
  }
  FillTriangle(WalkerCorners(corners, illumination, {}), frame,
               [&](int, int, const Attributes& a) { return surface.color * a.illumination; });
}

// "Phong Shading": the normal's three components carried across the triangle, and
// the light computed at every pixel. The interpolated normal is shorter than 1
// between the corners, so it is normalised again.
void ShadePhong(const std::array<ShadedCorner, 3>& corners, const Surface& surface,
                const Lighting& lighting, Frame& frame) {
  const std::array<Vec3, 3> normals = CornerNormals(corners, lighting.shading.normals);
  FillTriangle(WalkerCorners(corners, {}, normals), frame, [&](int x, int y, const Attributes& a) {
    const Vec3 P = UnProjectVertex(x, y, a.inv_z, frame.canvas, frame.viewport);
    const Vec3 N = glm::normalize(a.normal);
    return surface.color *
           ComputeLighting(P, N, -P, surface.specular, lighting.lights, lighting.shading.terms);
  });
}

void ShadeTriangle(const std::array<ShadedCorner, 3>& corners, const Surface& surface,
                   const Lighting& lighting, Frame& frame) {
  switch (lighting.shading.model) {
    case ShadingModel::kFlat:
      ShadeFlat(corners, surface, lighting, frame);
      break;
    case ShadingModel::kGouraud:
      ShadeGouraud(corners, surface, lighting, frame);
      break;
    case ShadingModel::kPhong:
      ShadePhong(corners, surface, lighting, frame);
      break;
  }
}
