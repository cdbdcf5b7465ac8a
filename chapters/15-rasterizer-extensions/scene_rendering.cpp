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

// "Environment Mapping": a cube map around each reflective instance, if the stage is
// on; indexed like the scene's instances.
std::vector<std::optional<CubeMap>> RenderEnvironments(const Scene& scene,
                                                       const Extensions& extensions) {
  std::vector<std::optional<CubeMap>> environments(scene.instances.size());
  for (std::size_t k = 0; k < scene.instances.size(); ++k) {
    const Instance& I = scene.instances[k];
    if (extensions.environment_mapping && I.model->reflective > 0) {
      environments[k] = RenderCubeMap(scene, I.transform.translation, extensions.cube_map_size);
    }
  }
  return environments;
}

// "Shadow Mapping": one shadow map per light, if the stage is on.
std::vector<ShadowMap> RenderShadowMaps(const Scene& scene, const Extensions& extensions) {
  std::vector<ShadowMap> shadow_maps;
  if (extensions.shadows == Shadows::kShadowMaps) {
    for (const Light& light : scene.lights) {
      shadow_maps.push_back(RenderShadowMap(scene, light, extensions.shadow_mapping));
    }
  }
  return shadow_maps;
}

// "The Clipping Pipeline": the instances in camera space, each with its cube map, and
// without its normal map unless that stage is on.
CameraSpaceScene ToCameraSpace(const Scene& scene, const glm::dmat4& M_camera,
                               const std::vector<std::optional<CubeMap>>& environments,
                               const Extensions& extensions) {
  CameraSpaceScene camera_space_scene;
  for (std::size_t k = 0; k < scene.instances.size(); ++k) {
    const Instance& I = scene.instances[k];
    CameraSpaceInstance instance =
        TransformToCameraSpace(I, M_camera * MakeTransformMatrix(I.transform));
    instance.environment = environments[k] ? &*environments[k] : nullptr;
    if (!extensions.normal_mapping) {
      instance.model.normal_map = nullptr;
    }
    camera_space_scene.instances.push_back(std::move(instance));
  }
  return camera_space_scene;
}

// Clipping, then "Back Face Culling" of the closed models.
CameraSpaceScene ClipAndCull(const CameraSpaceScene& scene, const std::vector<Plane>& planes) {
  CameraSpaceScene clipped_scene = ClipScene(scene, planes);
  const Vec3 camera(0, 0, 0);  // where the camera is, in camera space
  for (CameraSpaceInstance& I : clipped_scene.instances) {
    if (I.model.closed) {
      CullBackFaces(I.model, camera);
    }
  }
  return clipped_scene;
}

// "Stencil Shadows": the scene drawn in passes. First the ambient light alone, which
// also fills the depth buffer; then, for each other light, the shadow volumes of the
// closed occluders counted into the stencil (if `counting` is given), and the scene lit
// by that light alone added where the stencil is 0. The sum is clamped once, onto the
// canvas. `unclipped` is the scene in camera space, before clipping: a volume is cast
// by the whole occluder, seen or not.
void RenderInPasses(const CameraSpaceScene& unclipped, const Lighting& lighting,
                    const ShadowVolumeCounting* counting, const std::vector<Plane>& planes,
                    const std::function<void(const Lighting&)>& draw_all, Frame& frame) {
  AccumulationBuffer sum(frame.canvas);
  StencilBuffer stencil(frame.canvas);
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

// RenderScene's work for a view whose clipping volume is `planes`: the maps first,
// in world space, then the scene in camera space, clipped, culled and shaded, in one
// pass or in passes. Light is computed in camera space: the lights go through the
// camera matrix like the vertices.
void RenderView(const Scene& scene, const std::vector<Plane>& planes, Canvas& canvas,
                const Shading& shading, const Extensions& extensions) {
  const std::vector<std::optional<CubeMap>> environments = RenderEnvironments(scene, extensions);
  const std::vector<ShadowMap> shadow_maps = RenderShadowMaps(scene, extensions);

  const glm::dmat4 M_camera = MakeCameraMatrix(scene.camera.position, scene.camera.orientation);
  const CameraSpaceScene camera_space_scene =
      ToCameraSpace(scene, M_camera, environments, extensions);
  const CameraSpaceScene clipped_scene = ClipAndCull(camera_space_scene, planes);

  DepthBuffer depth_buffer(canvas, DepthValue::kInverseZ);
  Frame frame(canvas, depth_buffer, scene.viewport);
  frame.camera_to_world = glm::inverse(M_camera);
  Lighting lighting{TransformLights(scene.lights, M_camera), shading, {}};
  for (const ShadowMap& shadow_map : shadow_maps) {
    lighting.shadow_maps.push_back(&shadow_map);
  }
  const auto draw_all = [&](const Lighting& pass_lighting) {
    for (const CameraSpaceInstance& I : clipped_scene.instances) {
      RenderObject(I.model, I.environment, pass_lighting, frame);
    }
  };
  const bool shadow_volumes = extensions.shadows == Shadows::kShadowVolumes;
  if (extensions.multipass_lighting || shadow_volumes) {
    RenderInPasses(camera_space_scene, lighting,
                   shadow_volumes ? &extensions.shadow_volume_counting : nullptr, planes, draw_all,
                   frame);
  } else {
    draw_all(lighting);
  }
}

}  // namespace

// "The Clipping Pipeline": model space to camera space with one matrix per
// instance, then clipping, then projection. Clipping happens in camera space, where
// the clipping volume does not depend on the camera. What survives lies beyond the
// near plane, so RenderObject (Listing 10-1) can project and draw it.
void RenderScene(const Scene& scene, Canvas& canvas, const Shading& shading,
                 const Extensions& extensions) {
  RenderView(scene, ClippingPlanes(scene.viewport.distance), canvas, shading, extensions);
}

namespace {

// A sphere around every vertex of every instance, in world space.
BoundingSphere SceneBounds(const Scene& scene) {
  std::vector<Vec3> everything;
  for (const Instance& I : scene.instances) {
    for (const Vec3& V : I.model->vertices) {
      everything.push_back(ApplyTransform(V, I.transform));
    }
  }
  return ComputeBoundingSphere(everything);
}

// The clipping volume of a map's 90-degree view of size x size pixels: opened two
// pixels beyond its edges.
std::vector<Plane> MapClippingPlanes(double d, int size) {
  return ClippingPlanes(d, 1 + 4.0 / size);
}

}  // namespace

double NearPlaneOfMaps(const Scene& scene) {
  return SceneBounds(scene).radius / 1000;
}

CubeMap RenderCubeMap(const Scene& scene, const Vec3& centre, int size) {
  Scene surroundings = scene;
  const double d = NearPlaneOfMaps(scene);
  surroundings.viewport = {2 * d, 2 * d, d};
  surroundings.instances.clear();
  for (const Instance& instance : scene.instances) {
    if (instance.model->reflective == 0) {
      surroundings.instances.push_back(instance);
    }
  }
  CubeMap cube_map;
  for (int f = 0; f < 6; ++f) {
    const auto face = static_cast<CubeFace>(f);
    surroundings.camera = {centre, CubeFaceOrientation(face)};
    Canvas canvas(size, size);
    RenderView(surroundings, MapClippingPlanes(d, size), canvas, {}, {});
    cube_map.faces[static_cast<std::size_t>(f)] = TextureFromImage(canvas.GetImage());
  }
  return cube_map;
}

namespace {

// The depths a DepthBuffer holds, row by row from the top.
std::vector<double> DepthsOf(const DepthBuffer& depth_buffer, int size) {
  std::vector<double> depths;
  depths.reserve(static_cast<std::size_t>(size) * static_cast<std::size_t>(size));
  for (int y = size / 2 - 1; y >= -size / 2; --y) {
    for (int x = -size / 2; x < size / 2; ++x) {
      depths.push_back(depth_buffer.At(x, y));
    }
  }
  return depths;
}

// The orientation (columns right, up, forward) of a view looking along `forward`.
glm::dmat4 LookAlong(const Vec3& forward) {
  const Vec3 f = glm::normalize(forward);
  const Vec3 helper = std::abs(f.y) < 0.9 ? Vec3(0, 1, 0) : Vec3(1, 0, 0);
  const Vec3 right = glm::normalize(glm::cross(helper, f));
  const Vec3 up = glm::cross(f, right);
  return glm::dmat4(glm::dvec4(right, 0), glm::dvec4(up, 0), glm::dvec4(f, 0),
                    glm::dvec4(0, 0, 0, 1));
}

// A point light's view: every instance in the view's space, clipped like a cube map's
// face, drawn with the depth-buffered DrawFilledTriangle (the colours are not kept).
DepthMap PerspectiveView(const Scene& scene, const glm::dmat4& world_to_view, int size) {
  Canvas canvas(size, size);
  const double d = NearPlaneOfMaps(scene);
  const Viewport viewport{2 * d, 2 * d, d};
  DepthBuffer depth_buffer(canvas, DepthValue::kInverseZ);
  CameraSpaceScene view_scene;
  for (const Instance& I : scene.instances) {
    view_scene.instances.push_back(
        TransformToCameraSpace(I, world_to_view * MakeTransformMatrix(I.transform)));
  }
  for (const CameraSpaceInstance& I : ClipScene(view_scene, MapClippingPlanes(d, size)).instances) {
    const auto& V = I.model.vertices;
    for (const Triangle& T : I.model.triangles) {
      DrawFilledTriangle(ProjectVertex(V[T.v[0]], canvas, viewport),
                         ProjectVertex(V[T.v[1]], canvas, viewport),
                         ProjectVertex(V[T.v[2]], canvas, viewport), V[T.v[0]].z, V[T.v[1]].z,
                         V[T.v[2]].z, cgfs::kBlack, canvas, depth_buffer);
    }
  }
  return {size, DepthsOf(depth_buffer, size), world_to_view, false, 1};
}

// A directional light's view: orthographic, so a point (x, y, z) of the view's
// space lands at (x, y) scaled to the canvas, whatever its z; z is linear across the
// canvas then, and the depth buffer stores z itself. The view stands beyond the
// scene, so nothing needs clipping.
DepthMap OrthographicView(const Scene& scene, const Vec3& direction, int size) {
  const BoundingSphere bounds = SceneBounds(scene);
  const Vec3 forward = -glm::normalize(direction);
  const glm::dmat4 world_to_view =
      MakeCameraMatrix(bounds.center - forward * (bounds.radius + 1), LookAlong(forward));
  Canvas canvas(size, size);
  const Viewport viewport{2 * bounds.radius, 2 * bounds.radius, 1};
  DepthBuffer depth_buffer(canvas, DepthValue::kZ);
  for (const Instance& I : scene.instances) {
    const glm::dmat4 M = world_to_view * MakeTransformMatrix(I.transform);
    std::vector<Vec3> V;
    std::vector<Point> projected;
    for (const Vec3& vertex : I.model->vertices) {
      V.push_back(cgfs::ToCartesian(M * glm::dvec4(vertex, 1.0)));
      projected.push_back(ViewportToCanvas(V.back().x, V.back().y, canvas, viewport));
    }
    for (const Triangle& T : I.model->triangles) {
      DrawFilledTriangle(projected[T.v[0]], projected[T.v[1]], projected[T.v[2]], V[T.v[0]].z,
                         V[T.v[1]].z, V[T.v[2]].z, cgfs::kBlack, canvas, depth_buffer);
    }
  }
  return {size, DepthsOf(depth_buffer, size), world_to_view, true, bounds.radius};
}

}  // namespace

ShadowMap RenderShadowMap(const Scene& scene, const Light& light, const ShadowMapping& settings) {
  ShadowMap shadow_map;
  shadow_map.light = light;
  shadow_map.settings = settings;
  if (light.type == LightType::kPoint) {
    for (int f = 0; f < 6; ++f) {
      const glm::dmat4 orientation = CubeFaceOrientation(static_cast<CubeFace>(f));
      shadow_map.views.push_back(
          PerspectiveView(scene, MakeCameraMatrix(light.position, orientation), settings.size));
    }
  } else if (light.type == LightType::kDirectional) {
    shadow_map.views.push_back(OrthographicView(scene, light.direction, settings.size));
  }
  return shadow_map;
}
