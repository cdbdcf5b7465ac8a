// Chapter 10, "Describing and Rendering a Scene", the rendering part, as chapters 11
// to 13 leave it: every instance seen from the camera, clipped, its back faces culled
// if it is closed, and its triangles shaded into a depth-buffered frame. Where the
// book reads a global (the canvas, the viewport, the scene), the function takes it as
// a last parameter.
#pragma once

#include <vector>

#include "scene.h"
#include "shading.h"

// Listing 10-1 with the depth buffer and light: the triangle shaded (ShadeTriangle)
// where it is closer than what the frame already shows. `object` is in camera space,
// like the lights; `projected` are its vertices' projections.
void RenderTriangle(const Triangle& triangle, const Model& object,
                    const std::vector<Point>& projected, const Lighting& lighting, Frame& frame);

// Listing 10-1: projects every vertex once (each is shared by several triangles),
// then draws every triangle; with the depth buffer their order does not matter.
// Every vertex must lie beyond the projection plane (see ProjectVertex).
void RenderObject(const Model& object, const Lighting& lighting, Frame& frame);

// "The Clipping Pipeline", "Back Face Culling", "Depth Buffering" and "Shading": every
// instance, seen from the scene's camera, clipped against the clipping volume; the
// back faces of closed models culled; the rest shaded as `shading` says, lit by the
// scene's lights, which are brought into camera space like the vertices.
void RenderScene(const Scene& scene, Canvas& canvas, const Shading& shading = {});
