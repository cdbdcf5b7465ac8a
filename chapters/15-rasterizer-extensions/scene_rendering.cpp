#include "scene_rendering.h"

#include "back_face_culling.h"

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

// Listing 10-1 with "Depth Buffering" and "Shading".
void RenderTriangle(const Triangle& triangle, const Model& object,
                    const std::vector<Point>& projected, const Lighting& lighting, Frame& frame,
                    PhongSteps& steps) {
  std::array<ShadedCorner, 3> corners;
  for (std::size_t k = 0; k < 3; ++k) {
    const auto i = static_cast<std::size_t>(triangle.v[k]);
    corners[k] = {object.vertices[i], projected[i], triangle.normals[k], triangle.uvs[k]};
  }
  steps.BeginTriangle(corners);
  ShadeTriangle(corners, {triangle.color, object.specular, object.texture}, lighting, frame, steps);
}

// Listing 10-1.
void RenderObject(const Model& object, const Lighting& lighting, Frame& frame, PhongSteps& steps) {
  const std::vector<Point> projected =
      ProjectUsedVertices(object.vertices, object.triangles, frame.canvas, frame.viewport);
  for (const Triangle& T : object.triangles) {
    RenderTriangle(T, object, projected, lighting, frame, steps);
  }
}

CameraSpaceScene SceneInView(const Scene& scene, const glm::dmat4& M_camera) {
  CameraSpaceScene camera_space_scene;
  for (const Instance& I : scene.instances) {
    const glm::dmat4 M = M_camera * MakeTransformMatrix(I.transform);
    camera_space_scene.instances.push_back(TransformToCameraSpace(I, M));
  }
  return camera_space_scene;
}

// "The Clipping Pipeline": model space to camera space with one matrix per
// instance, then clipping, then projection. Clipping happens in camera space, where
// the clipping volume does not depend on the camera. What survives lies beyond the
// near plane, so RenderObject (Listing 10-1) can project and draw it. Back faces are
// culled after clipping and before drawing. Light is computed in camera space: the
// lights go through the camera matrix like the vertices.
void RenderView(const Scene& scene, const std::vector<Plane>& planes, const Shading& shading,
                const LightsOfPass& pass, Frame& frame, PhongSteps& steps, BackFaces back_faces) {
  const glm::dmat4 M_camera = MakeCameraMatrix(scene.camera.position, scene.camera.orientation);
  const CameraSpaceScene camera_space_scene = SceneInView(scene, M_camera);
  const std::vector<Light> lights = TransformLights(scene.lights, M_camera);
  Lighting lighting{{}, shading};
  for (std::size_t k = 0; k < lights.size(); ++k) {
    if (pass.Includes(k, lights[k])) {
      lighting.lights.push_back(lights[k]);
    }
  }

  const Vec3 camera(0, 0, 0);  // where the camera is, in camera space
  for (std::size_t k = 0; k < camera_space_scene.instances.size(); ++k) {
    std::optional<CameraSpaceInstance> clipped =
        ClipInstance(camera_space_scene.instances[k], planes);
    if (!clipped) {
      continue;
    }
    if (clipped->model.closed && back_faces == BackFaces::kCulled) {
      CullBackFaces(clipped->model, camera);
    }
    steps.BeginInstance(k, pass);
    RenderObject(clipped->model, lighting, frame, steps);
  }
}
