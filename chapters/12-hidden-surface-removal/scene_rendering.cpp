#include "scene_rendering.h"

#include "back_face_culling.h"
#include "clipping.h"
#include "painters_algorithm.h"

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

// Listing 10-1, filled ("Rendering Solid Objects").
void RenderTriangle(const Triangle& triangle, const std::vector<Point>& projected, Canvas& canvas) {
  DrawFilledTriangle(projected[triangle.v[0]], projected[triangle.v[1]], projected[triangle.v[2]],
                     triangle.color, canvas);
}

// Listing 10-1 with "Depth Buffering".
void RenderTriangle(const Triangle& triangle, const std::vector<Vec3>& vertices,
                    const std::vector<Point>& projected, Canvas& canvas, DepthBuffer& depth_buffer,
                    bool outlines) {
  const auto [i0, i1, i2] = triangle.v;
  DrawFilledTriangle(projected[i0], projected[i1], projected[i2], vertices[i0].z, vertices[i1].z,
                     vertices[i2].z, triangle.color, canvas, depth_buffer);
  if (outlines) {
    DrawWireframeTriangle(projected[i0], projected[i1], projected[i2], 0.75 * triangle.color,
                          canvas);
  }
}

// Listing 10-1.
void RenderObject(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles,
                  Canvas& canvas, const Viewport& viewport) {
  const std::vector<Point> projected = ProjectUsedVertices(vertices, triangles, canvas, viewport);
  for (const Triangle& T : triangles) {
    RenderTriangle(T, projected, canvas);
  }
}

// Listing 10-1 with "Depth Buffering".
void RenderObject(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles,
                  Canvas& canvas, const Viewport& viewport, DepthBuffer& depth_buffer,
                  bool outlines) {
  const std::vector<Point> projected = ProjectUsedVertices(vertices, triangles, canvas, viewport);
  for (const Triangle& T : triangles) {
    RenderTriangle(T, vertices, projected, canvas, depth_buffer, outlines);
  }
}

// "The Clipping Pipeline": model space to camera space with one matrix per
// instance, then clipping, then projection. Clipping happens in camera space, where
// the clipping volume does not depend on the camera. What survives lies beyond the
// near plane, so RenderObject (Listing 10-1) can project and draw it. Chapter 12
// culls back faces after clipping and before drawing, and draws the triangles in
// the order `method` asks for; the depth buffer is one per frame.
void RenderScene(const Scene& scene, Canvas& canvas, const HiddenSurfaceRemoval& method) {
  const glm::dmat4 M_camera = MakeCameraMatrix(scene.camera.position, scene.camera.orientation);
  CameraSpaceScene camera_space_scene;
  for (const Instance& I : scene.instances) {
    const glm::dmat4 M = M_camera * MakeTransformMatrix(I.transform);
    camera_space_scene.instances.push_back(TransformToCameraSpace(I, M));
  }
  const std::vector<Plane> planes = ClippingPlanes(scene.viewport.distance);
  CameraSpaceScene clipped_scene = ClipScene(camera_space_scene, planes);

  if (method.cull_back_faces) {
    const Vec3 camera(0, 0, 0);  // where the camera is, in camera space
    for (CameraSpaceInstance& I : clipped_scene.instances) {
      if (I.model.closed) {
        CullBackFaces(I.model, camera);
      }
    }
  }

  switch (method.draw_order) {
    case DrawOrder::kModelOrder:
      for (const CameraSpaceInstance& I : clipped_scene.instances) {
        RenderObject(I.model.vertices, I.model.triangles, canvas, scene.viewport);
      }
      break;
    case DrawOrder::kPaintersAlgorithm:
      PaintersAlgorithm(clipped_scene, canvas, scene.viewport);
      break;
    case DrawOrder::kDepthBuffer: {
      DepthBuffer depth_buffer(canvas, method.depth_value);
      for (const CameraSpaceInstance& I : clipped_scene.instances) {
        RenderObject(I.model.vertices, I.model.triangles, canvas, scene.viewport, depth_buffer,
                     method.outlines);
      }
      break;
    }
  }
}
