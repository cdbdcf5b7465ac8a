#include "scene_rendering.h"

#include <functional>
#include <optional>

#include "back_face_culling.h"
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

// Listing 10-1 with "Depth Buffering" and "Shading".
void RenderTriangle(const Triangle& triangle, const Model& object,
                    const std::vector<Point>& projected, const CubeMap* environment,
                    const Lighting& lighting, Frame& frame) {
  std::array<ShadedCorner, 3> corners;
  for (std::size_t k = 0; k < 3; ++k) {
    const auto i = static_cast<std::size_t>(triangle.v[k]);
    corners[k] = {object.vertices[i], projected[i], triangle.normals[k], triangle.uvs[k]};
  }
  const Surface surface{triangle.color,    object.specular,   object.texture,
                        object.normal_map, object.reflective, environment};
  ShadeTriangle(corners, surface, lighting, frame);
}

// Listing 10-1.
void RenderObject(const Model& object, const CubeMap* environment, const Lighting& lighting,
                  Frame& frame) {
  const std::vector<Point> projected =
      ProjectUsedVertices(object.vertices, object.triangles, frame.canvas, frame.viewport);
  for (const Triangle& T : object.triangles) {
    RenderTriangle(T, object, projected, environment, lighting, frame);
  }
}

namespace {

// "The Clipping Pipeline": the instances in camera space, without their normal maps
// unless that stage is on.
CameraSpaceScene ToCameraSpace(const Scene& scene, const glm::dmat4& M_camera,
                               const Extensions& extensions) {
  CameraSpaceScene camera_space_scene;
  for (const Instance& I : scene.instances) {
    CameraSpaceInstance instance =
        TransformToCameraSpace(I, M_camera * MakeTransformMatrix(I.transform));
    if (!extensions.normal_mapping) {
      instance.model.normal_map = nullptr;
    }
    camera_space_scene.instances.push_back(std::move(instance));
  }
  return camera_space_scene;
}

// An instance as it is drawn: its model in camera space, clipped, its back faces culled
// if it is closed, and the cube map it reflects, if any.
struct DrawnInstance {
  Model model;
  const CubeMap* environment = nullptr;
};

// Clipping as Listing 11-1 does it (ClipScene), each instance kept with its cube map;
// then "Back Face Culling" of the closed models.
std::vector<DrawnInstance> ClipAndCull(const CameraSpaceScene& scene, const Maps& maps,
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
    const bool reflects = k < maps.environments.size() && maps.environments[k];
    drawn.push_back({std::move(clipped->model), reflects ? &*maps.environments[k] : nullptr});
  }
  return drawn;
}

// "Stencil Shadows": the scene drawn in passes. First the ambient light alone, which
// also fills the depth buffer; then, for each other light, the shadow volumes of the
// closed occluders counted into the stencil (if `counting` is given), and the scene lit
// by that light alone added where the stencil is 0. The sum is clamped once, onto the
// canvas. `unclipped` is the scene in camera space, before clipping: a volume is cast
// by the whole occluder, seen or not. The stencil's writes are counted into
// `stencil_writes` if given.
void RenderInPasses(const CameraSpaceScene& unclipped, const Lighting& lighting,
                    const ShadowVolumeCounting* counting, std::vector<long>* stencil_writes,
                    const std::vector<Plane>& planes,
                    const std::function<void(const Lighting&)>& draw_all, Frame& frame) {
  AccumulationBuffer sum(frame.canvas);
  StencilBuffer stencil(frame.canvas);
  stencil.CountWrites(stencil_writes);
  Lighting pass_lighting = lighting;
  pass_lighting.lights.clear();
  pass_lighting.shadow_maps.clear();  // ambient light casts no shadows
  for (const Light& light : lighting.lights) {
    if (light.type == LightType::kAmbient) {
      pass_lighting.lights.push_back(light);
    }
  }
  frame.pass = {&sum, true, nullptr};
  draw_all(pass_lighting);

  for (std::size_t k = 0; k < lighting.lights.size(); ++k) {
    const Light& light = lighting.lights[k];
    if (light.type == LightType::kAmbient) {
      continue;
    }
    stencil.Clear();
    for (const CameraSpaceInstance& I : unclipped.instances) {
      if (counting && I.model.closed) {
        MarkShadowVolume(BuildShadowVolume(I.model, light), planes, frame.canvas, frame.viewport,
                         frame.depth_buffer, stencil, *counting);
      }
    }
    sum.BeginPass();
    pass_lighting.lights = {light};
    if (!lighting.shadow_maps.empty()) {
      pass_lighting.shadow_maps = {lighting.shadow_maps[k]};
    }
    frame.pass = {&sum, false, counting ? &stencil : nullptr};
    draw_all(pass_lighting);
  }
  sum.WriteTo(frame.canvas);
}

}  // namespace

// Light is computed in camera space: the lights go through the camera matrix like the
// vertices.
void RenderView(const Scene& scene, const Maps& maps, const std::vector<Plane>& planes,
                Canvas& canvas, const Shading& shading, const Extensions& extensions) {
  const glm::dmat4 M_camera = MakeCameraMatrix(scene.camera.position, scene.camera.orientation);
  const CameraSpaceScene camera_space_scene = ToCameraSpace(scene, M_camera, extensions);
  const std::vector<DrawnInstance> drawn = ClipAndCull(camera_space_scene, maps, planes);

  DepthBuffer depth_buffer(canvas, DepthValue::kInverseZ);
  Frame frame(canvas, depth_buffer, scene.viewport);
  frame.camera_to_world = glm::inverse(M_camera);
  frame.shadow_entries = extensions.shadow_entries;
  Lighting lighting{TransformLights(scene.lights, M_camera), shading, {}};
  for (const ShadowMap& shadow_map : maps.shadow_maps) {
    lighting.shadow_maps.push_back(&shadow_map);
  }
  const auto draw_all = [&](const Lighting& pass_lighting) {
    for (const DrawnInstance& I : drawn) {
      RenderObject(I.model, I.environment, pass_lighting, frame);
    }
  };
  const bool shadow_volumes = extensions.shadows == Shadows::kShadowVolumes;
  if (extensions.multipass_lighting || shadow_volumes) {
    RenderInPasses(camera_space_scene, lighting,
                   shadow_volumes ? &extensions.shadow_volume_counting : nullptr,
                   extensions.stencil_writes, planes, draw_all, frame);
  } else {
    draw_all(lighting);
  }
}

namespace {

// The maps the stages on read: "Environment Mapping", a cube map around each reflective
// instance (indexed like the instances); "Shadow Mapping", one shadow map per light.
Maps RenderMaps(const Scene& scene, const Extensions& extensions) {
  Maps maps;
  maps.environments.resize(scene.instances.size());
  for (std::size_t k = 0; k < scene.instances.size(); ++k) {
    const Instance& I = scene.instances[k];
    if (extensions.environment_mapping && I.model->reflective > 0) {
      maps.environments[k] =
          RenderCubeMap(scene, I.transform.translation, extensions.cube_map_size);
    }
  }
  if (extensions.shadows == Shadows::kShadowMaps) {
    for (const Light& light : scene.lights) {
      maps.shadow_maps.push_back(RenderShadowMap(scene, light, extensions.shadow_mapping));
    }
  }
  return maps;
}

}  // namespace

// "The Clipping Pipeline": model space to camera space with one matrix per
// instance, then clipping, then projection. Clipping happens in camera space, where
// the clipping volume does not depend on the camera. What survives lies beyond the
// near plane, so RenderObject (Listing 10-1) can project and draw it. "Extending the
// Rasterizer": first the maps the stages read, each made by rendering the scene from
// elsewhere, then the view from the camera, in one pass or in passes.
void RenderScene(const Scene& scene, Canvas& canvas, const Shading& shading,
                 const Extensions& extensions) {
  const Maps maps = RenderMaps(scene, extensions);
  RenderView(scene, maps, ClippingPlanes(scene.viewport.distance), canvas, shading, extensions);
}
