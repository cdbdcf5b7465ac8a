#include "shading.h"

#include "cgfs/tally.h"
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
  return {a.inv_z + b.inv_z, a.illumination + b.illumination, a.normal + b.normal, a.uv + b.uv};
}

Attributes operator-(const Attributes& a, const Attributes& b) {
  return {a.inv_z - b.inv_z, a.illumination - b.illumination, a.normal - b.normal, a.uv - b.uv};
}

Attributes operator*(const Attributes& a, double k) {
  return {a.inv_z * k, a.illumination * k, a.normal * k, a.uv * k};
}

Attributes operator/(const Attributes& a, double k) {
  return {a.inv_z / k, a.illumination / k, a.normal / k, a.uv / k};
}

glm::dvec2 CarriedTextureCoordinates(const glm::dvec2& uv, double z, const Texturing& texturing) {
  return texturing.interpolation == TextureInterpolation::kPerspectiveCorrect ? uv / z : uv;
}

glm::dvec2 TextureCoordinates(const Attributes& attributes, const Texturing& texturing) {
  return texturing.interpolation == TextureInterpolation::kPerspectiveCorrect
             ? attributes.uv / attributes.inv_z
             : attributes.uv;
}

namespace {

// The change per pixel, across (x) and up (y) the canvas, of a value that is linear
// on the canvas, from its values at the triangle's three projected corners.
glm::dvec2 ScreenGradient(const std::array<ShadedCorner, 3>& corners,
                          const std::array<double, 3>& a) {
  const double x1 = corners[1].projected.x - corners[0].projected.x;
  const double y1 = corners[1].projected.y - corners[0].projected.y;
  const double x2 = corners[2].projected.x - corners[0].projected.x;
  const double y2 = corners[2].projected.y - corners[0].projected.y;
  const double det = x1 * y2 - x2 * y1;
  if (det == 0) {
    return {0, 0};  // a triangle seen edge-on covers no area
  }
  const double a1 = a[1] - a[0];
  const double a2 = a[2] - a[0];
  return {(a1 * y2 - a2 * y1) / det, (x1 * a2 - x2 * a1) / det};
}

}  // namespace

CarriedGradients ComputeCarriedGradients(const std::array<ShadedCorner, 3>& corners,
                                         const Texturing& texturing) {
  std::array<double, 3> u{}, v{}, inv_z{};
  for (std::size_t k = 0; k < 3; ++k) {
    const glm::dvec2 carried =
        CarriedTextureCoordinates(corners[k].uv, corners[k].position.z, texturing);
    u[k] = carried.x;
    v[k] = carried.y;
    inv_z[k] = 1 / corners[k].position.z;
  }
  return {ScreenGradient(corners, u), ScreenGradient(corners, v), ScreenGradient(corners, inv_z)};
}

double TexelsPerPixel(const glm::dvec2& duv_dx, const glm::dvec2& duv_dy, const Texture& texture) {
  const glm::dvec2 size(texture.width, texture.height);
  return std::max(glm::length(duv_dx * size), glm::length(duv_dy * size));
}

// With u = (u/z) / (1/z), the quotient rule gives du = (d(u/z) - u d(1/z)) / (1/z).
Color SurfaceColor(const Surface& surface, const Attributes& attributes,
                   const CarriedGradients& gradients, const Texturing& texturing) {
  if (!surface.texture) {
    return surface.color;
  }
  const glm::dvec2 uv = TextureCoordinates(attributes, texturing);
  const bool perspective_correct =
      texturing.interpolation == TextureInterpolation::kPerspectiveCorrect;
  const double iz = attributes.inv_z;
  const glm::dvec2 du =
      perspective_correct ? (gradients.u - uv.x * gradients.inv_z) / iz : gradients.u;
  const glm::dvec2 dv =
      perspective_correct ? (gradients.v - uv.y * gradients.inv_z) / iz : gradients.v;
  const double rho = TexelsPerPixel({du.x, dv.x}, {du.y, dv.y}, surface.texture->levels.front());
  return SampleTexture(*surface.texture, uv.x, uv.y, rho, texturing.filter);
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

// The corners as the walker takes them: where each lands, and its 1/z, illumination,
// normal and texture coordinates.
std::array<WalkerCorner<Attributes>, 3> WalkerCorners(const std::array<ShadedCorner, 3>& corners,
                                                      const std::array<double, 3>& illumination,
                                                      const std::array<Vec3, 3>& normals,
                                                      const Texturing& texturing) {
  std::array<WalkerCorner<Attributes>, 3> walker_corners;
  for (std::size_t k = 0; k < 3; ++k) {
    const double z = corners[k].position.z;
    walker_corners[k] = {corners[k].projected,
                         {1 / z, illumination[k], normals[k],
                          CarriedTextureCoordinates(corners[k].uv, z, texturing)}};
  }
  return walker_corners;
}

// Every pixel of the triangle that passes the depth test gets shade(x, y, attributes).
template <typename Shade>
void FillTriangle(const std::array<WalkerCorner<Attributes>, 3>& corners, Frame& frame,
                  const Shade& shade) {
  WalkTriangle(corners, [&](int x, int y, const Attributes& attributes) {
    const cgfs::CurrentPixel current(x, y);  // where the work of chapter 15's stages is counted
    if (frame.TestAndSet(x, y, attributes.inv_z)) {
      frame.Write(x, y, shade(x, y, attributes));
    }
  });
}

}  // namespace

void ShadeFlat(const std::array<ShadedCorner, 3>& corners, const Surface& surface,
               const Lighting& lighting, Frame& frame) {
  const double illumination = FlatIllumination(corners, surface.specular, lighting);
  const Texturing& texturing = lighting.shading.texturing;
  const CarriedGradients gradients = ComputeCarriedGradients(corners, texturing);
  FillTriangle(WalkerCorners(corners, {}, {}, texturing), frame,
               [&](int, int, const Attributes& a) {
                 return SurfaceColor(surface, a, gradients, texturing) * illumination;
               });
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
  const Texturing& texturing = lighting.shading.texturing;
  const CarriedGradients gradients = ComputeCarriedGradients(corners, texturing);
  FillTriangle(WalkerCorners(corners, illumination, {}, texturing), frame,
               [&](int, int, const Attributes& a) {
                 return SurfaceColor(surface, a, gradients, texturing) * a.illumination;
               });
}

// "Phong Shading": the normal's three components carried across the triangle, and
// the light computed at every pixel. The interpolated normal is shorter than 1
// between the corners, so it is normalised again.
void ShadePhong(const std::array<ShadedCorner, 3>& corners, const Surface& surface,
                const Lighting& lighting, Frame& frame, const PhongSteps& steps) {
  const std::array<Vec3, 3> normals = CornerNormals(corners, lighting.shading.normals);
  const Texturing& texturing = lighting.shading.texturing;
  const CarriedGradients gradients = ComputeCarriedGradients(corners, texturing);
  PhongPixel pixel;
  FillTriangle(
      WalkerCorners(corners, {}, normals, texturing), frame,
      [&](int x, int y, const Attributes& a) {
        pixel.P = UnProjectVertex(x, y, a.inv_z, frame.canvas, frame.viewport);
        pixel.N = glm::normalize(a.normal);
        pixel.uv = TextureCoordinates(a, texturing);
        steps.Before(pixel);
        return steps.After(
            pixel, SurfaceColor(surface, a, gradients, texturing) *
                       ComputeLighting(pixel.P, pixel.N, -pixel.P, surface.specular,
                                       lighting.lights, lighting.shading.terms, pixel.visibility));
      });
}

void ShadeTriangle(const std::array<ShadedCorner, 3>& corners, const Surface& surface,
                   const Lighting& lighting, Frame& frame, const PhongSteps& steps) {
  switch (lighting.shading.model) {
    case ShadingModel::kFlat:
      ShadeFlat(corners, surface, lighting, frame);
      break;
    case ShadingModel::kGouraud:
      ShadeGouraud(corners, surface, lighting, frame);
      break;
    case ShadingModel::kPhong:
      ShadePhong(corners, surface, lighting, frame, steps);
      break;
  }
}
