#include "environment_mapping.h"

#include <cmath>

#include "scene_rendering.h"

// Chapter 4, "Reflections".
Vec3 ReflectRay(const Vec3& R, const Vec3& N) {
  return 2.0 * N * glm::dot(N, R) - R;
}

Color MixReflection(const Color& local, const Vec3& P, const Vec3& N, const CubeMap* environment,
                    double reflective, bool first_pass, const glm::dmat4& camera_to_world) {
  if (!environment || reflective == 0) {
    return local;
  }
  Color reflected(0, 0, 0);
  if (first_pass) {
    const Vec3 R = ReflectRay(-P, N);
    reflected = SampleCubeMap(*environment, Vec3(camera_to_world * glm::dvec4(R, 0.0)));
  }
  return (1 - reflective) * local + reflective * reflected;
}

Color SampleCubeMap(const CubeMap& cube_map, const Vec3& R) {
  const CubeMapPoint point = CubeMapLookup(R);
  const Texture& face = cube_map.faces[static_cast<std::size_t>(point.face)];
  return GetTexel(face, point.s * face.width, point.t * face.height - 1);
}

CubeMap RenderCubeMap(const Scene& scene, const Vec3& centre, int size) {
  Scene surroundings = scene;
  surroundings.instances.clear();
  for (const Instance& instance : scene.instances) {
    if (instance.model->reflective == 0) {
      surroundings.instances.push_back(instance);
    }
  }
  const Viewport viewport = CubeFaceViewport(scene);
  const std::vector<Plane> planes = CubeFaceClippingPlanes(viewport.distance, size);
  PhongSteps none;
  CubeMap cube_map;
  for (int f = 0; f < 6; ++f) {
    Canvas canvas(size, size);
    DepthBuffer depth_buffer(canvas, DepthValue::kInverseZ);
    Frame frame(canvas, depth_buffer, viewport);
    const Scene seen = CubeFaceView(surroundings, centre, static_cast<CubeFace>(f), viewport);
    RenderView(seen, planes, {}, {}, frame, none);
    cube_map.faces[static_cast<std::size_t>(f)] = TextureFromImage(canvas.GetImage());
  }
  return cube_map;
}
