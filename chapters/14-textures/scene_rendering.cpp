#include "scene_rendering.h"

#include "back_face_culling.h"
#include "clipping.h"
#include "painters_algorithm.h"

// Listing 10-1, filled ("Rendering Solid Objects").
void RenderTriangle(const Triangle& triangle, const std::vector<Point>& projected, Canvas& canvas) {
  DrawFilledTriangle(projected[triangle.v[0]], projected[triangle.v[1]], projected[triangle.v[2]],
                     triangle.color, canvas);
}

// Listing 10-1 with "Depth Buffering" and "Shading".
void RenderTriangle(const Triangle& triangle, const std::vector<Vec3>& vertices,
                    const std::vector<Point>& projected, double specular,
                    const MipmappedTexture* texture, const Lighting& lighting, Canvas& canvas,
                    const Viewport& viewport, DepthBuffer& depth_buffer, bool outlines) {
  const auto [i0, i1, i2] = triangle.v;
  const std::array<ShadedCorner, 3> corners = {{
      {vertices[i0], projected[i0], triangle.normals[0], triangle.uvs[0]},
      {vertices[i1], projected[i1], triangle.normals[1], triangle.uvs[1]},
      {vertices[i2], projected[i2], triangle.normals[2], triangle.uvs[2]},
  }};
  ShadeTriangle(corners, triangle.color, specular, lighting, canvas, viewport, depth_buffer,
                texture);
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
    RenderTriangle(T, object.vertices, projected, object.specular, object.texture, lighting, canvas,
                   viewport, depth_buffer, outlines);
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

// "The Clipping Pipeline": model space to camera space with one matrix per
// instance, then clipping, then projection. Clipping happens in camera space, where
// the clipping volume does not depend on the camera. What survives lies beyond the
// near plane, so RenderObject (Listing 10-1) can project and draw it. Chapter 12
// culls back faces after clipping and before drawing, and draws the triangles in
// the order `method` asks for; the depth buffer is one per frame. Chapter 13 lights
// in camera space: the lights go through the camera matrix like the vertices.
void RenderScene(const Scene& scene, Canvas& canvas, const HiddenSurfaceRemoval& method,
                 const Shading& shading) {
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
      const Lighting lighting{TransformLights(scene.lights, M_camera), shading};
      for (const CameraSpaceInstance& I : clipped_scene.instances) {
        RenderObject(I.model, lighting, canvas, scene.viewport, depth_buffer, method.outlines);
      }
      break;
    }
  }
}
