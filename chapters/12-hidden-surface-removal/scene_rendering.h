// Chapter 10, "Describing and Rendering a Scene", the rendering part: a scene's
// models drawn from their vertices and triangles, under the book's names. Where the
// book reads a global (the canvas, the viewport, the scene), the function takes it as
// a last parameter.
#pragma once

#include <vector>

#include "depth_buffer.h"
#include "scene.h"

// Listing 10-1, as chapter 12 begins: draws a triangle of a model from its projected
// vertices with DrawFilledTriangle instead of DrawWireframeTriangle (Figure 12-1).
void RenderTriangle(const Triangle& triangle, const std::vector<Point>& projected, Canvas& canvas);

// Listing 10-1 with the depth buffer: the triangle filled where it is closer than what
// is already drawn. `vertices` are in camera space, `projected` their projections.
// With `outlines`, its edges are then drawn in 0.75 x its colour, over whatever is
// there (the edges are not depth-tested).
void RenderTriangle(const Triangle& triangle, const std::vector<Vec3>& vertices,
                    const std::vector<Point>& projected, Canvas& canvas, DepthBuffer& depth_buffer,
                    bool outlines = false);

// Listing 10-1: projects every vertex once (each is shared by several triangles),
// then draws every triangle, in the order of the list. Every vertex must lie beyond
// the projection plane (see ProjectVertex).
void RenderObject(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles,
                  Canvas& canvas, const Viewport& viewport);

// Listing 10-1 with the depth buffer: the order of the triangles no longer matters.
void RenderObject(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles,
                  Canvas& canvas, const Viewport& viewport, DepthBuffer& depth_buffer,
                  bool outlines = false);

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

// "The Clipping Pipeline" and chapter 12: every instance, seen from the scene's
// camera, clipped against the clipping volume; the back faces of closed models
// culled; the rest drawn as solid triangles.
void RenderScene(const Scene& scene, Canvas& canvas, const HiddenSurfaceRemoval& method = {});
