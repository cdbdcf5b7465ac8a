#include "scene_rendering.h"

#include <functional>

#include "back_face_culling.h"
#include "clipping.h"
#include "painters_algorithm.h"
#include "shadow_volumes.h"

// Listing 10-1, filled ("Rendering Solid Objects").
void RenderTriangle(const Triangle& triangle, const std::vector<Point>& projected, Canvas& canvas) {
  DrawFilledTriangle(projected[triangle.v[0]], projected[triangle.v[1]], projected[triangle.v[2]],
                     triangle.color, canvas);
}

// Listing 10-1 with "Depth Buffering" and "Shading".
void RenderTriangle(const Triangle& triangle, const std::vector<Vec3>& vertices,
                    const std::vector<Point>& projected, const Model& model,
                    const Lighting& lighting, Canvas& canvas, const Viewport& viewport,
                    DepthBuffer& depth_buffer, bool outlines) {
  const auto [i0, i1, i2] = triangle.v;
  const std::array<ShadedCorner, 3> corners = {{
      {vertices[i0], projected[i0], triangle.normals[0], triangle.uvs[0]},
      {vertices[i1], projected[i1], triangle.normals[1], triangle.uvs[1]},
      {vertices[i2], projected[i2], triangle.normals[2], triangle.uvs[2]},
  }};
  ShadeTriangle(corners, triangle.color, model.specular, lighting, canvas, viewport, depth_buffer,
                model.texture, model.normal_map, model.reflective);
  if (outlines) {
    DrawWireframeTriangle(projected[i0], projected[i1], projected[i2], 0.75 * triangle.color,
                          canvas);
  }
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

// Listing 10-1 with "Depth Buffering" and "Shading".
void RenderObject(const Model& object, const Lighting& lighting, Canvas& canvas,
                  const Viewport& viewport, DepthBuffer& depth_buffer, bool outlines) {
  std::vector<Point> projected;
  for (const Vec3& V : object.vertices) {
    projected.push_back(ProjectVertex(V, canvas, viewport));
  }
  for (const Triangle& T : object.triangles) {
    RenderTriangle(T, object.vertices, projected, object, lighting, canvas, viewport, depth_buffer,
                   outlines);
  }
}

// Listing 10-4. Rotation and scale act about the model's origin, so translation comes last.
Vec3 ApplyTransform(const Vec3& vertex, const Transform& transform) {
  const Vec3 scaled = vertex * transform.scale;
  const Vec3 rotated = Vec3(transform.rotation * glm::dvec4(scaled, 0.0));
  const Vec3 translated = rotated + transform.translation;
  return translated;
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

// "The Transform Matrix": M_model = I_T * I_R * I_S, so the scale acts first.
glm::dmat4 MakeTransformMatrix(const Transform& transform) {
  return MakeTranslationMatrix(transform.translation) * transform.rotation *
         MakeScalingMatrix(transform.scale);
}

// "The Transform Matrix": M_camera = C_R^-1 * C_T^-1.
glm::dmat4 MakeCameraMatrix(const Vec3& position, const glm::dmat4& orientation) {
  return glm::transpose(orientation) * MakeTranslationMatrix(-position);
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

namespace {

// Chapter 15, "Stencil Shadows": the scene drawn in passes. First the ambient light
// alone, which also fills the depth buffer; then, for each other light, the shadow
// volumes of the closed occluders counted into the stencil (with shadow volumes),
// and the scene lit by that light alone added where the stencil is 0. The sum is
// clamped once, onto the canvas.
void RenderInPasses(const Viewport& viewport, const CameraSpaceScene& unclipped,
                    const Lighting& lighting, const std::function<void(Lighting)>& draw_all,
                    bool shadow_volumes, ShadowVolumeCounting counting, Canvas& canvas,
                    DepthBuffer& depth_buffer) {
  AccumulationBuffer sum(canvas);
  StencilBuffer stencil(canvas);
  Lighting pass_lighting = lighting;
  pass_lighting.lights.clear();
  pass_lighting.shadow_maps.clear();  // ambient light casts no shadows
  for (const Light& light : lighting.lights) {
    if (light.type == LightType::kAmbient) {
      pass_lighting.lights.push_back(light);
    }
  }
  pass_lighting.pass = {&sum, true, nullptr};
  draw_all(pass_lighting);

  const std::vector<Plane> planes = ClippingPlanes(viewport.distance);
  for (std::size_t k = 0; k < lighting.lights.size(); ++k) {
    const Light& light = lighting.lights[k];
    if (light.type == LightType::kAmbient) {
      continue;
    }
    stencil.Clear();
    if (shadow_volumes) {
      for (const CameraSpaceInstance& I : unclipped.instances) {
        if (I.model.closed) {
          MarkShadowVolume(BuildShadowVolume(I.model, light), planes, canvas, viewport,
                           depth_buffer, stencil, counting);
        }
      }
    }
    sum.BeginPass();
    pass_lighting.lights = {light};
    if (!lighting.shadow_maps.empty()) {
      pass_lighting.shadow_maps = {lighting.shadow_maps[k]};
    }
    pass_lighting.pass = {&sum, false, shadow_volumes ? &stencil : nullptr};
    draw_all(pass_lighting);
  }
  sum.WriteTo(canvas);
}

}  // namespace

// "The Clipping Pipeline": model space to camera space with one matrix per
// instance, then clipping, then projection. Clipping happens in camera space, where
// the clipping volume does not depend on the camera. What survives lies beyond the
// near plane, so RenderObject (Listing 10-1) can project and draw it. Chapter 12
// culls back faces after clipping and before drawing, and draws the triangles in
// the order `method` asks for; the depth buffer is one per frame. Chapter 13 lights
// in camera space: the lights go through the camera matrix like the vertices.
// Chapter 15 makes the cube maps and shadow maps first, in world space.
void RenderScene(const Scene& scene, Canvas& canvas, const HiddenSurfaceRemoval& method,
                 const Shading& shading, const Extensions& extensions) {
  // "Environment Mapping": one cube map per reflective instance, around its centre.
  // Reserved in full, because the camera-space instances keep pointers into it.
  std::vector<CubeMap> environments;
  environments.reserve(scene.instances.size());
  // "Shadow Mapping": one shadow map per light.
  std::vector<ShadowMap> shadow_maps;
  if (extensions.shadows == Shadows::kShadowMaps) {
    for (const Light& light : scene.lights) {
      shadow_maps.push_back(RenderShadowMap(scene, light, extensions.shadow_mapping.size));
    }
  }

  const glm::dmat4 M_camera = MakeCameraMatrix(scene.camera.position, scene.camera.orientation);
  CameraSpaceScene camera_space_scene;
  for (const Instance& I : scene.instances) {
    const glm::dmat4 M = M_camera * MakeTransformMatrix(I.transform);
    camera_space_scene.instances.push_back(TransformToCameraSpace(I, M));
    if (extensions.environment_mapping && I.model->reflective > 0) {
      environments.push_back(
          RenderCubeMap(scene, I.transform.translation, extensions.cube_map_size));
      camera_space_scene.instances.back().environment = &environments.back();
    }
    if (!extensions.normal_mapping) {
      camera_space_scene.instances.back().model.normal_map = nullptr;
    }
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
      Lighting lighting;
      lighting.lights = TransformLights(scene.lights, M_camera);
      lighting.shading = shading;
      lighting.camera_to_world = glm::inverse(M_camera);
      for (const ShadowMap& shadow_map : shadow_maps) {
        lighting.shadow_maps.push_back(&shadow_map);
      }
      lighting.shadow_mapping = extensions.shadow_mapping;
      // Every object, lit as `pass_lighting` says (its lights and its pass).
      const auto draw_all = [&](Lighting pass_lighting) {
        for (const CameraSpaceInstance& I : clipped_scene.instances) {
          pass_lighting.environment = I.environment;
          RenderObject(I.model, pass_lighting, canvas, scene.viewport, depth_buffer,
                       method.outlines);
        }
      };
      const bool shadow_volumes = extensions.shadows == Shadows::kShadowVolumes;
      if (extensions.multipass_lighting || shadow_volumes) {
        RenderInPasses(scene.viewport, camera_space_scene, lighting, draw_all, shadow_volumes,
                       extensions.shadow_volume_counting, canvas, depth_buffer);
      } else {
        draw_all(lighting);
      }
      break;
    }
  }
}
