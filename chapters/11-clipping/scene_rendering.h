// Chapter 10, "Describing and Rendering a Scene": models, instances, transforms and
// a camera, under the book's names. Where the book reads a global (the canvas, the
// viewport, the scene), the function takes it as a last parameter.
#pragma once

#include <array>
#include <vector>

#include <glm/mat4x4.hpp>

#include "matrices.h"
#include "projection.h"

// "Representing a Cube": a triangle is three indices into its model's vertex list, and a colour.
struct Triangle {
  std::array<int, 3> v{};
  Color color{0, 0, 0};
};

// "Models and Instances": a model is its geometry, in model space.
struct Model {
  std::vector<Vec3> vertices;
  std::vector<Triangle> triangles;
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
};

// Listing 10-1: draws a triangle of a model from its projected vertices.
void RenderTriangle(const Triangle& triangle, const std::vector<Point>& projected, Canvas& canvas);

// Listing 10-1: projects every vertex once (each is shared by several triangles),
// then draws every triangle as a wireframe. Every vertex must lie beyond the
// projection plane (see ProjectVertex).
void RenderObject(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles,
                  Canvas& canvas, const Viewport& viewport);

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

// "The Clipping Pipeline": every instance, seen from the scene's camera, clipped
// against the clipping volume, then drawn.
void RenderScene(const Scene& scene, Canvas& canvas);
