// Chapter 10, "Describing and Rendering a Scene", the rendering part, as chapters 11
// to 15 leave it: one view of a scene, every instance seen from its camera, clipped,
// its back faces culled if it is closed, and its triangles shaded into a depth-buffered
// frame, with whatever a renderer adds to Phong shading. The camera's view of the scene
// is one (RenderScene, extensions.h, which adds chapter 15's stages), a pass of
// multi-pass lighting is one (multipass_lighting.h), and so is each face of a cube map
// (environment_mapping.h) and each view of a point light's shadow map
// (shadow_mapping.h). Where the book reads a global (the canvas, the viewport, the
// scene), the function takes it as a last parameter.
#pragma once

#include <vector>

#include "clipping.h"
#include "scene.h"
#include "shading.h"

// Listing 10-1 with the depth buffer and light: the triangle shaded (ShadeTriangle)
// where it is closer than what the frame already shows. `object` is in camera space,
// like the lights; `projected` are its vertices' projections.
void RenderTriangle(const Triangle& triangle, const Model& object,
                    const std::vector<Point>& projected, const Lighting& lighting, Frame& frame,
                    PhongSteps& steps);

// Listing 10-1: projects every vertex once (each is shared by several triangles),
// then draws every triangle; with the depth buffer their order does not matter.
// Every vertex must lie beyond the projection plane (see ProjectVertex).
void RenderObject(const Model& object, const Lighting& lighting, Frame& frame, PhongSteps& steps);

// "The Clipping Pipeline", its first step: the scene's instances in the space of the
// view whose camera matrix is M_camera, one matrix per instance.
CameraSpaceScene SceneInView(const Scene& scene, const glm::dmat4& M_camera);

// Whether a view culls the back faces of closed models ("Back Face Culling"). A shadow
// map's view draws them: where the rasteriser leaves a gap along the outline of an
// occluder's front faces, its back faces still cast the shadow.
enum class BackFaces { kCulled, kDrawn };

// One view of the scene into `frame`, which the caller owns (its canvas, depth buffer and
// viewport): every instance seen from the scene's camera, clipped against `planes`, the
// back faces of closed models culled (unless kDrawn), the rest shaded as `shading` says
// with `steps` added, lit by the pass's lights, which are brought into camera space like
// the vertices.
void RenderView(const Scene& scene, const std::vector<Plane>& planes, const Shading& shading,
                const LightsOfPass& pass, Frame& frame, PhongSteps& steps,
                BackFaces back_faces = BackFaces::kCulled);
