// Chapter 13, "Shading": spreading the light computed at points over whole
// triangles. Flat, Gouraud and Phong shading, and UnProjectVertex.
#pragma once

#include <array>
#include <vector>

#include "depth_buffer.h"
#include "lighting.h"
#include "projection.h"

// "Flat Shading", "Gouraud Shading", "Phong Shading", in order of cost and quality.
enum class ShadingModel { kFlat, kGouraud, kPhong };

// "Normals": where a triangle's normals come from. kTriangle: computed from its
// three vertices, the same at every point of it; kModel: the model's normal at each
// corner (for a sphere, the true normal of the surface there).
enum class NormalSource { kTriangle, kModel };

// How the chapter's figures shade: one choice of each.
struct Shading {
  ShadingModel model = ShadingModel::kPhong;
  NormalSource normals = NormalSource::kModel;
  LightingTerms terms;
};

// What lighting a triangle needs besides the triangle: the scene's lights in camera
// space, and the shading to use.
struct Lighting {
  std::vector<Light> lights;
  Shading shading;
};

// What a triangle is made of: its colour, and how shiny it is (chapter 3's specular
// exponent, -1 for matte).
struct Surface {
  Color color{0, 0, 0};
  double specular = -1;
};

// Where shaded pixels go: the canvas, behind a 1/z depth buffer, and the viewport
// that maps the scene onto it.
struct Frame {
  Frame(Canvas& target, DepthBuffer& depths, const Viewport& shown)
      : canvas(target), depth_buffer(depths), viewport(shown) {}

  Canvas& canvas;
  DepthBuffer& depth_buffer;
  Viewport viewport;

  // "Depth Buffering": whether the point at 1/z = inv_z is closer than what pixel
  // (x, y) shows (and if so, it is now what the pixel shows).
  bool TestAndSet(int x, int y, double inv_z) { return depth_buffer.TestAndSet(x, y, inv_z); }
  void Write(int x, int y, const Color& color) { canvas.PutPixel(x, y, color); }
};

// "Flat Shading": the unit normal of the triangle's plane, (B - A) x (C - A)
// normalised; it points out of a model wound as "Classifying Triangles" requires.
Vec3 ComputeTriangleNormal(const Vec3& A, const Vec3& B, const Vec3& C);

// "Phong Shading": the camera-space point that canvas pixel (x, y) shows, from the
// 1/z interpolated there. ProjectVertex in reverse: x' = X * d / Z gives X = x' * Z / d.
Vec3 UnProjectVertex(int x, int y, double inv_z, const Canvas& canvas, const Viewport& viewport);

// One corner of a triangle, as shading needs it: the camera-space vertex, where it
// lands on the canvas, and its normal in camera space.
struct ShadedCorner {
  Vec3 position;
  Point projected;
  Vec3 normal;
};

// What each corner carries across the triangle to its pixels (WalkTriangle): 1/z,
// for the depth test and UnProjectVertex; the illumination, for Gouraud shading; and
// the normal, for Phong shading.
struct Attributes {
  double inv_z = 0;
  double illumination = 0;
  Vec3 normal{0, 0, 0};
};
Attributes operator+(const Attributes& a, const Attributes& b);
Attributes operator-(const Attributes& a, const Attributes& b);
Attributes operator*(const Attributes& a, double k);
Attributes operator/(const Attributes& a, double k);

// The normals the shading uses at the three corners, unit length: the corners' own,
// or (kTriangle) the triangle's, ComputeTriangleNormal.
std::array<Vec3, 3> CornerNormals(const std::array<ShadedCorner, 3>& corners, NormalSource source);

// "Flat Shading": the illumination the whole triangle has: the light at its
// centroid, with the average of its corners' normals (for kTriangle normals, the
// triangle's own normal). V = -P: in camera space the camera is at the origin.
double FlatIllumination(const std::array<ShadedCorner, 3>& corners, double specular,
                        const Lighting& lighting);

// The three ways of shading a triangle, each filling it (depth-tested) with the
// surface's colour times the illumination: computed once for the triangle (flat), at
// its corners and interpolated (Gouraud), or at every pixel, from the interpolated
// normal and the point UnProjectVertex rebuilds (Phong). `corners` in the triangle's
// own order.
void ShadeFlat(const std::array<ShadedCorner, 3>& corners, const Surface& surface,
               const Lighting& lighting, Frame& frame);
void ShadeGouraud(const std::array<ShadedCorner, 3>& corners, const Surface& surface,
                  const Lighting& lighting, Frame& frame);
void ShadePhong(const std::array<ShadedCorner, 3>& corners, const Surface& surface,
                const Lighting& lighting, Frame& frame);

// The triangle shaded as lighting.shading says.
void ShadeTriangle(const std::array<ShadedCorner, 3>& corners, const Surface& surface,
                   const Lighting& lighting, Frame& frame);
