// Chapter 13, "Shading": spreading the light computed at points over whole
// triangles. Flat, Gouraud and Phong shading, and UnProjectVertex.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include <glm/vec2.hpp>

#include "depth_buffer.h"
#include "lighting.h"
#include "mipmap.h"
#include "projection.h"

// "Flat Shading", "Gouraud Shading", "Phong Shading", in order of cost and quality.
enum class ShadingModel { kFlat, kGouraud, kPhong };

// "Normals": where a triangle's normals come from. kTriangle: computed from its
// three vertices, the same at every point of it; kModel: the model's normal at each
// corner (for a sphere, the true normal of the surface there).
enum class NormalSource { kTriangle, kModel };

// How texture coordinates are carried across a triangle. Affine carries u and v like
// any attribute, which is wrong (Figure 14-3): like z, they are not linear on the
// canvas. u/z and v/z are, like 1/z, so carrying them and dividing by the carried 1/z
// gives the right u and v (Figure 14-5). The illumination (Gouraud) and the normal
// (Phong) stay affine, as the book leaves them: their error is small where a triangle
// covers little depth, and they change slowly.
enum class TextureInterpolation { kAffine, kPerspectiveCorrect };

// How a textured triangle reads its texture.
struct Texturing {
  TextureInterpolation interpolation = TextureInterpolation::kPerspectiveCorrect;
  TextureFilter filter = TextureFilter::kTrilinear;
};

// How the chapter's figures shade: one choice of each.
struct Shading {
  ShadingModel model = ShadingModel::kPhong;
  NormalSource normals = NormalSource::kModel;
  LightingTerms terms;
  Texturing texturing;
};

// What lighting a triangle needs besides the triangle: the scene's lights in camera
// space, and the shading to use.
struct Lighting {
  std::vector<Light> lights;
  Shading shading;
};

// What a triangle is made of: its colour, how shiny it is (chapter 3's specular
// exponent, -1 for matte), and the texture that takes the colour's place, if any.
struct Surface {
  Color color{0, 0, 0};
  double specular = -1;
  const MipmappedTexture* texture = nullptr;
};

// Where shaded pixels go: the canvas, behind a 1/z depth buffer, and the viewport
// that maps the scene onto it. A pass of multi-pass lighting sends them elsewhere
// (multipass_lighting.h's PassFrame).
struct Frame {
  Frame(Canvas& target, DepthBuffer& depths, const Viewport& shown)
      : canvas(target), depth_buffer(depths), viewport(shown) {}
  virtual ~Frame() = default;

  Canvas& canvas;
  DepthBuffer& depth_buffer;
  Viewport viewport;

  // "Depth Buffering": whether the point at 1/z = inv_z is closer than what pixel
  // (x, y) shows (and if so, it is now what the pixel shows).
  virtual bool TestAndSet(int x, int y, double inv_z) {
    return depth_buffer.TestAndSet(x, y, inv_z);
  }
  virtual void Write(int x, int y, const Color& color) { canvas.PutPixel(x, y, color); }
};

// "Flat Shading": the unit normal of the triangle's plane, (B - A) x (C - A)
// normalised; it points out of a model wound as "Classifying Triangles" requires.
Vec3 ComputeTriangleNormal(const Vec3& A, const Vec3& B, const Vec3& C);

// "Phong Shading": the camera-space point that canvas pixel (x, y) shows, from the
// 1/z interpolated there. ProjectVertex in reverse: x' = X * d / Z gives X = x' * Z / d.
Vec3 UnProjectVertex(int x, int y, double inv_z, const Canvas& canvas, const Viewport& viewport);

// One corner of a triangle, as shading needs it: the camera-space vertex, where it
// lands on the canvas, its normal in camera space, and its texture coordinates (u, v).
struct ShadedCorner {
  Vec3 position;
  Point projected;
  Vec3 normal;
  glm::dvec2 uv{0, 0};
};

// What each corner carries across the triangle to its pixels (WalkTriangle): 1/z,
// for the depth test and UnProjectVertex; the illumination, for Gouraud shading; the
// normal, for Phong shading; and the texture coordinates, (u, v) or (u/z, v/z).
struct Attributes {
  double inv_z = 0;
  double illumination = 0;
  Vec3 normal{0, 0, 0};
  glm::dvec2 uv{0, 0};
};
Attributes operator+(const Attributes& a, const Attributes& b);
Attributes operator-(const Attributes& a, const Attributes& b);
Attributes operator*(const Attributes& a, double k);
Attributes operator/(const Attributes& a, double k);

// "Perspective-Correct Texture Mapping": what a corner at depth z carries for texture
// coordinates uv, and the (u, v) a pixel gets back from what it was carried: u/z and
// v/z, divided by the carried 1/z; or (affine) u and v themselves.
glm::dvec2 CarriedTextureCoordinates(const glm::dvec2& uv, double z, const Texturing& texturing);
glm::dvec2 TextureCoordinates(const Attributes& attributes, const Texturing& texturing);

// How fast the carried texture coordinates and 1/z change from one pixel to the next
// across (x) and up (y) the canvas, each (d/dx, d/dy): the same everywhere on a
// triangle, since they are linear on the canvas.
struct CarriedGradients {
  glm::dvec2 u{0, 0};
  glm::dvec2 v{0, 0};
  glm::dvec2 inv_z{0, 0};
};
CarriedGradients ComputeCarriedGradients(const std::array<ShadedCorner, 3>& corners,
                                         const Texturing& texturing);

// "Mipmapping": texels per pixel at a point of a textured triangle, from how fast the
// texel coordinates (u * width, v * height) change from one pixel to the next across
// and up the canvas, whichever is faster.
double TexelsPerPixel(const glm::dvec2& duv_dx, const glm::dvec2& duv_dy, const Texture& texture);

// The surface's colour at a pixel: its texture's, sampled at the pixel's (u, v) with
// the filter `texturing` asks for, or its own colour if it has no texture. The change
// of u and v per pixel, for TexelsPerPixel, is the quotient rule applied to the
// carried gradients (perspective-correct), or the gradients themselves (affine).
Color SurfaceColor(const Surface& surface, const Attributes& attributes,
                   const CarriedGradients& gradients, const Texturing& texturing);

// The normals the shading uses at the three corners, unit length: the corners' own,
// or (kTriangle) the triangle's, ComputeTriangleNormal.
std::array<Vec3, 3> CornerNormals(const std::array<ShadedCorner, 3>& corners, NormalSource source);

// "Flat Shading": the illumination the whole triangle has: the light at its
// centroid, with the average of its corners' normals (for kTriangle normals, the
// triangle's own normal). V = -P: in camera space the camera is at the origin.
double FlatIllumination(const std::array<ShadedCorner, 3>& corners, double specular,
                        const Lighting& lighting);

// What Phong shading knows of a pixel: the camera-space point it shows, the unit normal
// there, its texture coordinates, and how much of each light reaches the point (none
// given: all of every light).
struct PhongPixel {
  Vec3 P;
  Vec3 N;
  glm::dvec2 uv;
  std::vector<double> visibility;
};

// The lights a view is drawn with: all the scene's (in one pass), or, in multi-pass
// lighting, its ambient lights (the frame's first pass) or light number k alone (each
// later pass).
struct LightsOfPass {
  enum class Which { kAll, kAmbient, kOne };
  Which which = Which::kAll;
  std::size_t k = 0;  // with kOne

  // Whether the pass is lit by the scene's light number `index`, `light`.
  bool Includes(std::size_t index, const Light& light) const {
    return which == Which::kAll ||
           (which == Which::kAmbient && light.type == LightType::kAmbient) ||
           (which == Which::kOne && index == k);
  }
  bool First() const { return which != Which::kOne; }  // the frame's first pass, or only one
};

// What a renderer adds to Phong shading, as one object for a whole render (the
// shader of tinyrenderer's rasteriser): set up for each instance a pass draws and for
// each triangle, then at each pixel Before may bend the normal and keep light from the
// point, After may change the lit colour. These add nothing; chapter 15's stages do
// (extensions.cpp).
class PhongSteps {
 public:
  virtual ~PhongSteps() = default;
  // The scene's instance `instance` is drawn next, in `pass`.
  virtual void BeginInstance(std::size_t /*instance*/, const LightsOfPass& /*pass*/) {}
  // Its triangle with these corners is shaded next.
  virtual void BeginTriangle(const std::array<ShadedCorner, 3>& /*corners*/) {}
  virtual void Before(PhongPixel& /*pixel*/) const {}
  virtual Color After(const PhongPixel& /*pixel*/, const Color& lit) const { return lit; }
};

// The three ways of shading a triangle, each filling it (depth-tested) with the
// surface's colour (SurfaceColor) times the illumination: computed once for the triangle (flat), at
// its corners and interpolated (Gouraud), or at every pixel, from the interpolated
// normal and the point UnProjectVertex rebuilds (Phong, with the steps a renderer
// adds). `corners` in the triangle's own order.
void ShadeFlat(const std::array<ShadedCorner, 3>& corners, const Surface& surface,
               const Lighting& lighting, Frame& frame);
void ShadeGouraud(const std::array<ShadedCorner, 3>& corners, const Surface& surface,
                  const Lighting& lighting, Frame& frame);
void ShadePhong(const std::array<ShadedCorner, 3>& corners, const Surface& surface,
                const Lighting& lighting, Frame& frame, const PhongSteps& steps = {});

// The triangle shaded as lighting.shading says.
void ShadeTriangle(const std::array<ShadedCorner, 3>& corners, const Surface& surface,
                   const Lighting& lighting, Frame& frame, const PhongSteps& steps = {});
