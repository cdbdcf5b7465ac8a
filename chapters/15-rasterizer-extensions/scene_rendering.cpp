#include "scene_rendering.h"

#include <numeric>

#include "back_face_culling.h"
#include "multipass_lighting.h"
#include "stencil_buffer.h"

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
                    const PhongStepsOf& steps) {
  std::array<ShadedCorner, 3> corners;
  for (std::size_t k = 0; k < 3; ++k) {
    const auto i = static_cast<std::size_t>(triangle.v[k]);
    corners[k] = {object.vertices[i], projected[i], triangle.normals[k], triangle.uvs[k]};
  }
  const std::unique_ptr<PhongSteps> added = steps ? steps(corners) : nullptr;
  const PhongSteps none;
  ShadeTriangle(corners, {triangle.color, object.specular, object.texture}, lighting, frame,
                added ? *added : none);
}

// Listing 10-1.
void RenderObject(const Model& object, const Lighting& lighting, Frame& frame,
                  const PhongStepsOf& steps) {
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

namespace {

// An instance as it is drawn: its model in camera space, clipped, its back faces culled
// if it is closed; and which of the scene's instances it is.
struct DrawnInstance {
  Model model;
  std::size_t instance = 0;
};

// Clipping as Listing 11-1 does it (ClipScene), each instance kept with its index;
// then "Back Face Culling" of the closed models.
std::vector<DrawnInstance> ClipAndCull(const CameraSpaceScene& scene,
                                       const std::vector<Plane>& planes) {
  std::vector<DrawnInstance> drawn;
  const Vec3 camera(0, 0, 0);  // where the camera is, in camera space
  for (std::size_t k = 0; k < scene.instances.size(); ++k) {
    std::optional<CameraSpaceInstance> clipped = ClipInstance(scene.instances[k], planes);
    if (!clipped) {
      continue;
    }
    if (clipped->model.closed) {
      CullBackFaces(clipped->model, camera);
    }
    drawn.push_back({std::move(clipped->model), k});
  }
  return drawn;
}

// Draws the view's instances with the lights of a pass (their indices among the scene's
// lights), into a frame; `first_pass` for the first pass or the only one.
using DrawPass =
    std::function<void(const std::vector<std::size_t>& lights, bool first_pass, Frame& frame)>;

// "Stencil Shadows": the scene drawn in passes. First the ambient light alone, which
// also fills the depth buffer; then, for each other light, the shadow volumes of the
// closed occluders counted into the stencil (if `counting` is given), and the scene lit
// by that light alone added where the stencil is 0. The sum is clamped once, onto the
// canvas. `unclipped` is the scene in camera space, before clipping: a volume is cast
// by the whole occluder, seen or not.
void RenderInPasses(const CameraSpaceScene& unclipped, const std::vector<Light>& lights,
                    const ShadowVolumeCounting* counting, const std::vector<Plane>& planes,
                    const DrawPass& draw_pass, Frame& frame) {
  AccumulationBuffer sum(frame.canvas);
  StencilBuffer stencil(frame.canvas);
  std::vector<std::size_t> ambient;
  for (std::size_t k = 0; k < lights.size(); ++k) {
    if (lights[k].type == LightType::kAmbient) {
      ambient.push_back(k);
    }
  }
  PassFrame first(frame.canvas, frame.depth_buffer, frame.viewport, {&sum, true, nullptr});
  draw_pass(ambient, true, first);

  for (std::size_t k = 0; k < lights.size(); ++k) {
    if (lights[k].type == LightType::kAmbient) {
      continue;
    }
    stencil.Clear();
    for (const CameraSpaceInstance& I : unclipped.instances) {
      if (counting && I.model.closed) {
        MarkShadowVolume(BuildShadowVolume(I.model, lights[k]), planes, frame.canvas,
                         frame.viewport, frame.depth_buffer, stencil, *counting);
      }
    }
    sum.BeginPass();
    PassFrame pass(frame.canvas, frame.depth_buffer, frame.viewport,
                   {&sum, false, counting ? &stencil : nullptr});
    draw_pass({k}, false, pass);
  }
  sum.WriteTo(frame.canvas);
}

}  // namespace

// Back faces are culled after clipping and before drawing; the depth buffer is one per
// view. Light is computed in camera space: the lights go through the camera matrix
// like the vertices.
void RenderView(const Scene& scene, const std::vector<Plane>& planes, Canvas& canvas,
                const Shading& shading, const ViewDrawing& drawing) {
  const glm::dmat4 M_camera = MakeCameraMatrix(scene.camera.position, scene.camera.orientation);
  const CameraSpaceScene camera_space_scene = SceneInView(scene, M_camera);
  const std::vector<DrawnInstance> drawn = ClipAndCull(camera_space_scene, planes);

  DepthBuffer depth_buffer(canvas, DepthValue::kInverseZ);
  Frame frame(canvas, depth_buffer, scene.viewport);
  const std::vector<Light> lights = TransformLights(scene.lights, M_camera);
  const DrawPass draw_pass = [&](const std::vector<std::size_t>& pass_lights, bool first_pass,
                                 Frame& target) {
    Lighting lighting{{}, shading};
    for (const std::size_t k : pass_lights) {
      lighting.lights.push_back(lights[k]);
    }
    for (const DrawnInstance& I : drawn) {
      PhongStepsOf steps;
      if (drawing.phong_steps) {
        steps = [&](const std::array<ShadedCorner, 3>& corners) {
          return drawing.phong_steps({I.instance, corners, pass_lights, first_pass});
        };
      }
      RenderObject(I.model, lighting, target, steps);
    }
  };
  if (drawing.multipass_lighting || drawing.shadow_volumes) {
    RenderInPasses(camera_space_scene, lights,
                   drawing.shadow_volumes ? &*drawing.shadow_volumes : nullptr, planes, draw_pass,
                   frame);
  } else {
    std::vector<std::size_t> all(lights.size());
    std::iota(all.begin(), all.end(), std::size_t{0});
    draw_pass(all, true, frame);
  }
}
