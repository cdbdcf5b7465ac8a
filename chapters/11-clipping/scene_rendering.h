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

// "The Clipping Pipeline": every instance, seen from the scene's camera, clipped
// against the clipping volume, then drawn.
void RenderScene(const Scene& scene, Canvas& canvas);
