// Chapter 10, "Describing and Rendering a Scene": models, instances, transforms and
// a camera, under the book's names. Where the book reads a global (the canvas, the
// viewport, the scene), the function takes it as a last parameter.
#pragma once

#include <array>
#include <vector>

#include <glm/mat4x4.hpp>

#include "depth_buffer.h"
#include "lighting.h"
#include "matrices.h"
#include "projection.h"
#include "shading.h"

// "Representing a Cube": a triangle is three indices into its model's vertex list, and a
// colour. Chapter 13, "Normals": and the surface's normal at each of its three corners,
// so that a vertex shared by several triangles can have a different normal in each.
// Chapter 14, "Painting a Crate": and the texture coordinates (u, v) of each corner.
struct Triangle {
  std::array<int, 3> v{};
  Color color{0, 0, 0};
  std::array<Vec3, 3> normals{};
  std::array<glm::dvec2, 3> uvs{};
};

// "Models and Instances": a model is its geometry, in model space. Closed means
// that from outside only its outer side can be seen ("Back Face Culling"); only a
// closed model may have its back faces culled.
struct Model {
  std::vector<Vec3> vertices;
  std::vector<Triangle> triangles;
  bool closed = true;
  double specular = 50;  // chapter 3's specular exponent, for the whole model
  // Chapter 14: the texture painted on every triangle (instead of its colour), or none.
  const MipmappedTexture* texture = nullptr;
  // Chapter 15: a normal map over the same (u, v), or none; and how much of its
  // surroundings the model reflects (0..1, like chapter 4's `reflective`).
  const Texture* normal_map = nullptr;
  double reflective = 0;
};

// "Model Transform" (Listing 10-4): applied as scale, then rotation, then translation.
struct Transform {
  double scale = 1;
  glm::dmat4 rotation{1.0};
  Vec3 translation{0, 0, 0};
};

// One placement of a model in the scene.
struct Instance {
  const Model* model = nullptr;
  Transform transform;
};

// "Camera Transform": where the camera is, and which way it looks.
struct Camera {
  Vec3 position{0, 0, 0};
  glm::dmat4 orientation{1.0};
};

struct Scene {
  Viewport viewport;
  Camera camera;
  std::vector<Instance> instances;
  std::vector<Light> lights;  // chapter 13: in world space, like the instances
};

// Listing 10-1, as chapter 12 begins: draws a triangle of a model from its projected
// vertices with DrawFilledTriangle instead of DrawWireframeTriangle (Figure 12-1).
void RenderTriangle(const Triangle& triangle, const std::vector<Point>& projected, Canvas& canvas);

// Listing 10-1 with the depth buffer and, from chapter 13, light: the triangle shaded
// (ShadeTriangle) where it is closer than what is already drawn. `vertices` are in
// camera space, `projected` their projections; the rest of the surface (its specular
// exponent, texture, normal map, reflectiveness) is the model's. With `outlines`, its
// edges are then drawn in 0.75 x its colour, over whatever is there (the edges are
// not depth-tested).
void RenderTriangle(const Triangle& triangle, const std::vector<Vec3>& vertices,
                    const std::vector<Point>& projected, const Model& model,
                    const Lighting& lighting, Canvas& canvas, const Viewport& viewport,
                    DepthBuffer& depth_buffer, bool outlines = false);

// Listing 10-1: projects every vertex once (each is shared by several triangles),
// then draws every triangle, in the order of the list. Every vertex must lie beyond
// the projection plane (see ProjectVertex).
void RenderObject(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles,
                  Canvas& canvas, const Viewport& viewport);

// Listing 10-1 with the depth buffer and light: the order of the triangles no longer
// matters. The object is in camera space, like `lighting`'s lights.
void RenderObject(const Model& object, const Lighting& lighting, Canvas& canvas,
                  const Viewport& viewport, DepthBuffer& depth_buffer, bool outlines = false);

// Listing 10-4: the vertex scaled, then rotated, then translated.
Vec3 ApplyTransform(const Vec3& vertex, const Transform& transform);

// Listing 10-3: an instance, each vertex transformed into the scene by
// ApplyTransform; the camera stays at the origin looking along +Z.
void RenderInstance(const Instance& instance, Canvas& canvas, const Viewport& viewport);

// "The Transform Matrix": I.transform of Listing 10-5, translation * rotation * scale.
glm::dmat4 MakeTransformMatrix(const Transform& transform);

// Listing 10-5: world space to camera space: the inverse of the camera's translation,
// then the inverse of its rotation (a rotation's inverse is its transpose).
glm::dmat4 MakeCameraMatrix(const Vec3& position, const glm::dmat4& orientation);

// Listing 10-5: every vertex through one matrix, projected, then every triangle drawn.
void RenderModel(const Model& model, const glm::dmat4& transform, Canvas& canvas,
                 const Viewport& viewport);

// Chapter 12: the ways of deciding which triangle a pixel shows, in the order the
// chapter tries them.
enum class DrawOrder {
  kModelOrder,         // "Rendering Solid Objects": as listed, far over near (Figure 12-1)
  kPaintersAlgorithm,  // "Painter's Algorithm": every triangle, back to front
  kDepthBuffer,        // "Depth Buffering": per pixel, the closest point wins
};

// How RenderScene draws what survives clipping; each figure of chapter 12 picks
// one. The defaults are where the chapter ends.
struct HiddenSurfaceRemoval {
  DrawOrder draw_order = DrawOrder::kDepthBuffer;
  DepthValue depth_value = DepthValue::kInverseZ;  // what the depth buffer stores
  bool cull_back_faces = true;                     // Listing 12-1, closed models only
  bool outlines = false;  // with the depth buffer: edges in 0.75 x the colour
};

// Chapter 15: the optional stages, each off by default (then RenderScene draws what
// chapter 14 draws). They need Phong shading and the depth buffer, except shadow
// volumes and multi-pass lighting, which work with any shading.
enum class Shadows {
  kNone,
  kShadowVolumes,  // "Stencil Shadows": exact, in passes, from closed models only
  kShadowMaps,     // "Shadow Mapping": from everything, as sharp as the maps are fine
};

// "Stencil Shadows": where along the view ray the stencil counts the volumes' faces.
enum class ShadowVolumeCounting {
  kDepthFail,  // behind the surface ("Carmack's reverse"): right wherever the camera is
  kDepthPass,  // in front of it, the first idea: wrong when the camera is in a shadow
};

struct Extensions {
  bool normal_mapping = false;       // models' normal maps bend their normals
  bool environment_mapping = false;  // reflective models reflect a cube map made around them
  int cube_map_size = 128;           // pixels per side of each face
  bool multipass_lighting = false;   // one pass per light, added up (shadow volumes need it)
  Shadows shadows = Shadows::kNone;
  ShadowVolumeCounting shadow_volume_counting = ShadowVolumeCounting::kDepthFail;
  ShadowMapping shadow_mapping;  // with kShadowMaps
};

// "The Clipping Pipeline" and chapter 12: every instance, seen from the scene's
// camera, clipped against the clipping volume; the back faces of closed models
// culled; the rest drawn as solid triangles. Chapter 13: with the depth buffer, lit
// by the scene's lights (brought into camera space) and shaded as `shading` says.
// Chapter 15: with the stages `extensions` turns on.
void RenderScene(const Scene& scene, Canvas& canvas, const HiddenSurfaceRemoval& method = {},
                 const Shading& shading = {}, const Extensions& extensions = {});
