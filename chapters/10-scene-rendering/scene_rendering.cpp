#include "scene_rendering.h"

// Listing 10-1.
void RenderTriangle(const Triangle& triangle, const std::vector<Point>& projected, Canvas& canvas) {
  DrawWireframeTriangle(projected[triangle.v[0]], projected[triangle.v[1]],
                        projected[triangle.v[2]], triangle.color, canvas);
}

// Listing 10-1.
void RenderObject(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles,
                  Canvas& canvas, const Viewport& viewport) {
  std::vector<Point> projected;
  for (const Vec3& V : vertices) {
    projected.push_back(ProjectVertex(V, canvas, viewport));
  }
  for (const Triangle& T : triangles) {
    RenderTriangle(T, projected, canvas);
  }
}

// Listing 10-3.
void RenderInstance(const Instance& instance, Canvas& canvas, const Viewport& viewport) {
  std::vector<Point> projected;
  const Model& model = *instance.model;
  for (const Vec3& V : model.vertices) {
    const Vec3 V_transformed = ApplyTransform(V, instance.transform);
    projected.push_back(ProjectVertex(V_transformed, canvas, viewport));
  }
  for (const Triangle& T : model.triangles) {
    RenderTriangle(T, projected, canvas);
  }
}

// Listing 10-5. Vertices are points: w = 1.
void RenderModel(const Model& model, const glm::dmat4& transform, Canvas& canvas,
                 const Viewport& viewport) {
  std::vector<Point> projected;
  for (const Vec3& V : model.vertices) {
    projected.push_back(
        ProjectVertex(cgfs::ToCartesian(transform * glm::dvec4(V, 1.0)), canvas, viewport));
  }
  for (const Triangle& T : model.triangles) {
    RenderTriangle(T, projected, canvas);
  }
}

// Listing 10-5. One matrix per instance takes its vertices from model space all
// the way to camera space.
void RenderScene(const Scene& scene, Canvas& canvas) {
  const glm::dmat4 M_camera = MakeCameraMatrix(scene.camera.position, scene.camera.orientation);
  for (const Instance& I : scene.instances) {
    const glm::dmat4 M = M_camera * MakeTransformMatrix(I.transform);
    RenderModel(*I.model, M, canvas, scene.viewport);
  }
}
