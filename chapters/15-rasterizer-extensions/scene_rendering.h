// Chapter 10, "Describing and Rendering a Scene", the rendering part, as chapters 11
// to 15 leave it: every instance seen from the camera, clipped, its back faces culled
// if it is closed, and its triangles shaded into a depth-buffered frame; with the
// optional stages of "Extending the Rasterizer", whose maps are made first. Where the
// book reads a global (the canvas, the viewport, the scene), the function takes it as
// a last parameter.
#pragma once

#include <optional>
#include <vector>

#include "clipping.h"
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
  // With kShadowVolumes: the stencil's writes per pixel, counted into this vector if
  // given (StencilBuffer::CountWrites), for a cost view.
  std::vector<long>* stencil_writes = nullptr;
  // With kShadowMaps: the entry of the (first) shadow map each pixel's lookup reads,
  // written into this vector if given (-1: none), for a cost view.
  std::vector<long>* shadow_entries = nullptr;
  ShadowMapping shadow_mapping;  // with kShadowMaps
};

// The maps the stages read, made before the scene is drawn: what each instance reflects
// ("Environment Mapping": a reflective instance's cube map, indexed like the instances)
// and ("Shadow Mapping") one shadow map per light.
struct Maps {
  std::vector<std::optional<CubeMap>> environments;
  std::vector<ShadowMap> shadow_maps;
};

// One view of the scene, its maps made: every instance seen from the scene's camera,
// clipped against `planes`, the back faces of closed models culled, the rest shaded as
// `shading` says, lit by the scene's lights, which are brought into camera space like
// the vertices; in one pass, or ("Stencil Shadows") in one pass per light.
void RenderView(const Scene& scene, const Maps& maps, const std::vector<Plane>& planes,
                Canvas& canvas, const Shading& shading, const Extensions& extensions);

// "The Clipping Pipeline", "Back Face Culling", "Depth Buffering" and "Shading", with
// the stages `extensions` turns on: the maps they read (RenderCubeMap, RenderShadowMap),
// then the view from the camera through the clipping volume (RenderView).
void RenderScene(const Scene& scene, Canvas& canvas, const Shading& shading = {},
                 const Extensions& extensions = {});
