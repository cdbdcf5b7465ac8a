// Chapter 10, "Describing and Rendering a Scene", the rendering part: a scene's
// models drawn from their vertices and triangles, under the book's names. Where the
// book reads a global (the canvas, the viewport, the scene), the function takes it as
// a last parameter.
#pragma once

#include <vector>

#include "scene.h"

// Listing 10-1: draws a triangle of a model from its projected vertices.
void RenderTriangle(const Triangle& triangle, const std::vector<Point>& projected, Canvas& canvas);

// Listing 10-1: projects every vertex once (each is shared by several triangles),
// then draws every triangle as a wireframe. Every vertex must lie beyond the
// projection plane (see ProjectVertex).
void RenderObject(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles,
                  Canvas& canvas, const Viewport& viewport);

// Listing 10-3: an instance, each vertex transformed into the scene by
// ApplyTransform; the camera stays at the origin looking along +Z.
void RenderInstance(const Instance& instance, Canvas& canvas, const Viewport& viewport);

// Listing 10-5: every vertex through one matrix, projected, then every triangle drawn.
void RenderModel(const Model& model, const glm::dmat4& transform, Canvas& canvas,
                 const Viewport& viewport);

// Listing 10-5: every instance, seen from the scene's camera.
void RenderScene(const Scene& scene, Canvas& canvas);
