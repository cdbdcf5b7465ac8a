// Chapter 13, "Shading": spreading the light computed at points over whole
// triangles. Flat, Gouraud and Phong shading, and UnProjectVertex.
#pragma once

#include <array>
#include <vector>

#include <glm/vec2.hpp>

#include "depth_buffer.h"
#include "environment_mapping.h"
#include "lighting.h"
#include "mipmap.h"
#include "multipass_lighting.h"
#include "projection.h"
#include "shadow_mapping.h"

// "Flat Shading", "Gouraud Shading", "Phong Shading", in order of cost and quality.
enum class ShadingModel { kFlat, kGouraud, kPhong };

// "Normals": where a triangle's normals come from. kTriangle: computed from its
// three vertices, the same at every point of it; kModel: the model's normal at each
// corner (for a sphere, the true normal of the surface there).
enum class NormalSource { kTriangle, kModel };

// Chapter 14: how texture coordinates are interpolated across a triangle. Affine
// interpolates u and v like any attribute, which is wrong (Figure 14-3): like z,
// they are not linear on the canvas. u/z and v/z are, like 1/z, so interpolating
// them and dividing by the interpolated 1/z gives the right u and v (Figure 14-5).
enum class TextureInterpolation { kAffine, kPerspectiveCorrect };

// Chapter 14: how a textured triangle reads its texture.
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
// space, and the shading to use. Chapter 15: where the camera-space points are in
// the world (cube maps and shadow maps are made in world space), what the object
// being drawn reflects, each light's shadow map, and the pass being drawn.
struct Lighting {
  std::vector<Light> lights;
  Shading shading;
  glm::dmat4 camera_to_world{1.0};
  const CubeMap* environment = nullptr;       // "Environment Mapping"
  std::vector<const ShadowMap*> shadow_maps;  // "Shadow Mapping": none, or one per light
  ShadowMapping shadow_mapping;
  Pass pass;  // "Stencil Shadows": one pass, unless multi-pass lighting says otherwise
};

// "Flat Shading": the unit normal of the triangle's plane, (B - A) x (C - A)
// normalised; it points out of a model wound as "Classifying Triangles" requires.
Vec3 ComputeTriangleNormal(const Vec3& A, const Vec3& B, const Vec3& C);

// "Phong Shading": the camera-space point that canvas pixel (x, y) shows, from the
// 1/z interpolated there. ProjectVertex in reverse: x' = X * d / Z gives X = x' * Z / d.
Vec3 UnProjectVertex(int x, int y, double inv_z, const Canvas& canvas, const Viewport& viewport);

// One corner of a triangle, as shading needs it: the camera-space vertex, where it
// lands on the canvas, its unit normal in camera space, and (chapter 14) its texture
// coordinates (u, v).
struct ShadedCorner {
  Vec3 position;
  Point projected;
  Vec3 normal;
  glm::dvec2 uv{0, 0};
};

// The illumination a flat-shaded triangle has everywhere: the light at its
// centroid, with the average of its corners' normals (for kTriangle normals, the
// triangle's own normal).
double FlatIllumination(const std::array<ShadedCorner, 3>& corners, double specular,
                        const Lighting& lighting);

// Chapter 14: texels per pixel at a point of a textured triangle, from how fast the
// texel coordinates (u * width, v * height) change from one pixel to the next across
// and up the canvas, whichever is faster.
double TexelsPerPixel(const glm::dvec2& duv_dx, const glm::dvec2& duv_dy, const Texture& texture);

// The triangle filled, depth-tested against a 1/z buffer, each pixel `color` times
// the illumination there: computed once (flat), at the corners and interpolated
// (Gouraud), or at every pixel from the interpolated normal and the point
// UnProjectVertex rebuilds (Phong). `corners` in the triangle's own order; with
// kTriangle normals the corners' normals are ignored. Chapter 14: with a texture,
// the texel at the pixel's (u, v) takes the place of `color`. Chapter 15, with Phong
// shading: a normal map bends the normal at every pixel; a surface `reflective`
// (0..1) mixes in the environment's colour in the reflected direction, as chapter 4
// mixes in the reflected ray's; each light is dimmed by its shadow map, if it has
// one; and the pixels go where lighting.pass sends them.
void ShadeTriangle(const std::array<ShadedCorner, 3>& corners, const Color& color, double specular,
                   const Lighting& lighting, Canvas& canvas, const Viewport& viewport,
                   DepthBuffer& depth_buffer, const MipmappedTexture* texture = nullptr,
                   const Texture* normal_map = nullptr, double reflective = 0);
