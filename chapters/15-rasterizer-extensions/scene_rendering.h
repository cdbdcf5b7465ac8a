// Chapter 10, "Describing and Rendering a Scene", the rendering part, as chapters 11
// to 15 leave it: one view of a scene, every instance seen from its camera, clipped,
// its back faces culled if it is closed, and its triangles shaded into a depth-buffered
// frame; in one pass, or ("Stencil Shadows") in passes; with whatever a renderer adds
// to Phong shading. The camera's view of the scene is one (RenderScene, extensions.h,
// which adds chapter 15's stages), and so is each face of a cube map
// (environment_mapping.h).
// Where the book reads a global (the canvas, the viewport, the scene), the function
// takes it as a last parameter.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "clipping.h"
#include "scene.h"
#include "shading.h"
#include "shadow_volumes.h"

// What a renderer adds to the Phong shading of one triangle, from its corners (none:
// chapter 13's shading).
using PhongStepsOf = std::function<std::unique_ptr<PhongSteps>(const std::array<ShadedCorner, 3>&)>;

// Listing 10-1 with the depth buffer and light: the triangle shaded (ShadeTriangle)
// where it is closer than what the frame already shows. `object` is in camera space,
// like the lights; `projected` are its vertices' projections.
void RenderTriangle(const Triangle& triangle, const Model& object,
                    const std::vector<Point>& projected, const Lighting& lighting, Frame& frame,
                    const PhongStepsOf& steps = {});

// Listing 10-1: projects every vertex once (each is shared by several triangles),
// then draws every triangle; with the depth buffer their order does not matter.
// Every vertex must lie beyond the projection plane (see ProjectVertex).
void RenderObject(const Model& object, const Lighting& lighting, Frame& frame,
                  const PhongStepsOf& steps = {});

// "The Clipping Pipeline", its first step: the scene's instances in the space of the
// view whose camera matrix is M_camera, one matrix per instance.
CameraSpaceScene SceneInView(const Scene& scene, const glm::dmat4& M_camera);

// A triangle as a view draws it, for the steps a renderer adds to its Phong shading:
// the scene's instance it belongs to, its corners, the lights the pass draws (their
// indices among the scene's lights) and whether the pass is the first (or the only one).
struct TriangleInView {
  std::size_t instance;
  const std::array<ShadedCorner, 3>& corners;
  const std::vector<std::size_t>& lights;
  bool first_pass;
};

// How a view is drawn beyond chapter 14's way: in passes ("Stencil Shadows" in them),
// and with steps added to Phong shading.
struct ViewDrawing {
  bool multipass_lighting = false;  // one pass per light, added up
  // "Stencil Shadows": the passes (which they need) counting shadow volumes this way.
  std::optional<ShadowVolumeCounting> shadow_volumes;
  std::function<std::unique_ptr<PhongSteps>(const TriangleInView&)> phong_steps;
};

// One view of the scene: every instance seen from the scene's camera, clipped against
// `planes`, the back faces of closed models culled, the rest shaded as `shading` says,
// lit by the scene's lights, which are brought into camera space like the vertices.
void RenderView(const Scene& scene, const std::vector<Plane>& planes, Canvas& canvas,
                const Shading& shading, const ViewDrawing& drawing = {});
