// Chapter 10, "Describing and Rendering a Scene", the rendering part, as chapters 11
// to 15 leave it: every instance seen from the camera, clipped, its back faces culled
// if it is closed, and its triangles shaded into a depth-buffered frame; with the
// optional stages of "Extending the Rasterizer", and beside RenderScene the passes
// that render the scene again, into cube maps and shadow maps. Where the book reads a
// global (the canvas, the viewport, the scene), the function takes it as a last
// parameter.
#pragma once

#include <vector>

#include "environment_mapping.h"
#include "scene.h"
#include "shading.h"
#include "shadow_mapping.h"
#include "shadow_volumes.h"

// Listing 10-1 with the depth buffer and light: the triangle shaded (ShadeTriangle)
// where it is closer than what the frame already shows. `object` is in camera space,
// like the lights; `projected` are its vertices' projections; `environment` is what it
// reflects, if anything.
void RenderTriangle(const Triangle& triangle, const Model& object,
                    const std::vector<Point>& projected, const CubeMap* environment,
                    const Lighting& lighting, Frame& frame);

// Listing 10-1: projects every vertex once (each is shared by several triangles),
// then draws every triangle; with the depth buffer their order does not matter.
// Every vertex must lie beyond the projection plane (see ProjectVertex).
void RenderObject(const Model& object, const CubeMap* environment, const Lighting& lighting,
                  Frame& frame);

// "Shadows": which technique, if any, keeps the light from what is behind an occluder.
enum class Shadows {
  kNone,
  kShadowVolumes,  // "Stencil Shadows": exact, in passes, from closed models only
  kShadowMaps,     // "Shadow Mapping": from everything, as sharp as the maps are fine
};

// The optional stages, each off by default (then RenderScene draws what chapter 14
// draws). Normal maps, reflections and shadow maps need Phong shading.
struct Extensions {
  bool normal_mapping = false;       // models' normal maps bend their normals
  bool environment_mapping = false;  // reflective models reflect a cube map made around them
  int cube_map_size = 128;           // pixels per side of each face
  bool multipass_lighting = false;   // one pass per light, added up (shadow volumes need it)
  Shadows shadows = Shadows::kNone;
  ShadowVolumeCounting shadow_volume_counting = ShadowVolumeCounting::kDepthFail;
  ShadowMapping shadow_mapping;  // with kShadowMaps
};

// "The Clipping Pipeline", "Back Face Culling", "Depth Buffering" and "Shading": every
// instance, seen from the scene's camera, clipped against the clipping volume; the
// back faces of closed models culled; the rest shaded as `shading` says, lit by the
// scene's lights, which are brought into camera space like the vertices; with the
// stages `extensions` turns on.
void RenderScene(const Scene& scene, Canvas& canvas, const Shading& shading = {},
                 const Extensions& extensions = {});

// The near plane of the views rendered for the maps: a thousandth of the radius of a
// sphere around every instance, so that nothing of the scene is cut away however
// close to a view's centre it is.
double NearPlaneOfMaps(const Scene& scene);

// "Environment Mapping": the surroundings seen from `centre`, six 90-degree views
// (viewport 2d x 2d at d = NearPlaneOfMaps), size x size pixels each: the scene's
// instances that reflect nothing, lit by its lights with the default (Phong) shading
// and no other stage, so reflections show no shadows. The reflective ones are left
// out: each would otherwise have to be in the others' maps, and its own map is made
// from inside it. The map is centred on the reflective object, not on the room as the
// book suggests: with one object, its centre is where the reflection is least wrong.
CubeMap RenderCubeMap(const Scene& scene, const Vec3& centre, int size);

// "Shadow Mapping": the scene's depths as `light` (in world space) sees them,
// settings.size x settings.size per view: six perspective views from a point light, one
// orthographic view along a directional light, covering a sphere around every
// instance's vertices and seen from beyond it; none for ambient light. No back faces
// are culled: a surface that faces away from the light casts a shadow too.
ShadowMap RenderShadowMap(const Scene& scene, const Light& light, const ShadowMapping& settings);
