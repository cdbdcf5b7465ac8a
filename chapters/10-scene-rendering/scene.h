// Chapter 10, "Describing and Rendering a Scene", the describing part: models,
// instances, transforms and a camera, under the book's names, and the transforms that
// take a vertex from a model into the scene and from the scene into the camera's view.
#pragma once

#include <array>
#include <vector>

#include <glm/mat4x4.hpp>

#include "cgfs/view.h"
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

// Listing 10-4: the vertex scaled, then rotated, then translated.
Vec3 ApplyTransform(const Vec3& vertex, const Transform& transform);

// "The Transform Matrix": I.transform of Listing 10-5, translation * rotation * scale.
glm::dmat4 MakeTransformMatrix(const Transform& transform);

// Listing 10-5: world space to camera space: the inverse of the camera's translation,
// then the inverse of its rotation (a rotation's inverse is its transpose).
glm::dmat4 MakeCameraMatrix(const Vec3& position, const glm::dmat4& orientation);

// The camera moved as --window or --view asks (cgfs::View): along its own right, up and
// forward axes (the columns of its orientation), then turned to the left (yaw, about its
// up axis) and up (pitch, about its right axis).
Camera MovedCamera(const Camera& camera, const cgfs::View& view);
