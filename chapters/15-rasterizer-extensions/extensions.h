// Chapter 15, "Extending the Rasterizer": chapter 10's RenderScene with the chapter's
// optional stages. The maps they read are made first, each by drawing the scene from
// elsewhere, then the view from the camera (RenderView, scene_rendering.h), the stages
// adding their steps to its Phong shading. Where the book reads a global (the canvas,
// the viewport, the scene), the function takes it as a last parameter.
#pragma once

#include <optional>
#include <vector>

#include "environment_mapping.h"
#include "scene.h"
#include "shading.h"
#include "shadow_mapping.h"
#include "shadow_volumes.h"

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

// The maps the stages read, made before the scene is drawn: what each instance reflects
// ("Environment Mapping": a reflective instance's cube map, indexed like the instances)
// and ("Shadow Mapping") one shadow map per light.
struct Maps {
  std::vector<std::optional<CubeMap>> environments;
  std::vector<ShadowMap> shadow_maps;
};

// "The Clipping Pipeline", "Back Face Culling", "Depth Buffering" and "Shading", with
// the stages `extensions` turns on: the maps they read (RenderCubeMap, RenderShadowMap),
// then the view from the camera through the clipping volume (RenderView).
void RenderScene(const Scene& scene, Canvas& canvas, const Shading& shading = {},
                 const Extensions& extensions = {});
