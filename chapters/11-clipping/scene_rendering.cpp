#include "scene_rendering.h"

#include "clipping.h"

namespace {

// Listing 10-1 projects every vertex once. After clipping, the list still holds the
// vertices clipping cut away, behind the projection plane, where ProjectVertex has no
// answer: only the vertices some triangle uses are projected.
std::vector<Point> ProjectUsedVertices(const std::vector<Vec3>& vertices,
                                       const std::vector<Triangle>& triangles, const Canvas& canvas,
                                       const Viewport& viewport) {
  std::vector<bool> used(vertices.size(), false);
  for (const Triangle& T : triangles) {
    for (const int i : T.v) {
      used[static_cast<std::size_t>(i)] = true;
    }
  }
  std::vector<Point> projected(vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    if (used[i]) {
      projected[i] = ProjectVertex(vertices[i], canvas, viewport);
    }
  }
  return projected;
}

}  // namespace

// Listing 10-1.
void RenderTriangle(const Triangle& triangle, const std::vector<Point>& projected, Canvas& canvas) {
  DrawWireframeTriangle(projected[triangle.v[0]], projected[triangle.v[1]],
                        projected[triangle.v[2]], triangle.color, canvas);
}

// Listing 10-1.
void RenderObject(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles,
                  Canvas& canvas, const Viewport& viewport) {
  const std::vector<Point> projected = ProjectUsedVertices(vertices, triangles, canvas, viewport);
  for (const Triangle& T : triangles) {
    RenderTriangle(T, projected, canvas);
  }
}

// "The Clipping Pipeline": model space to camera space with one matrix per
// instance, then clipping, then projection. Clipping happens in camera space, where
// the clipping volume does not depend on the camera. What survives lies beyond the
// near plane, so RenderObject (Listing 10-1) can project and draw it.
void RenderScene(const Scene& scene, Canvas& canvas) {
  const glm::dmat4 M_camera = MakeCameraMatrix(scene.camera.position, scene.camera.orientation);
  CameraSpaceScene camera_space_scene;
  for (const Instance& I : scene.instances) {
    const glm::dmat4 M = M_camera * MakeTransformMatrix(I.transform);
    camera_space_scene.instances.push_back(TransformToCameraSpace(I, M));
  }
  const std::vector<Plane> planes = ClippingPlanes(scene.viewport.distance);
  for (const CameraSpaceInstance& I : ClipScene(camera_space_scene, planes).instances) {
    RenderObject(I.model.vertices, I.model.triangles, canvas, scene.viewport);
  }
}
