#include "environment_mapping.h"

#include <cmath>

#include "scene_rendering.h"

glm::dmat4 CubeFaceOrientation(CubeFace face) {
  const auto orientation = [](const Vec3& right, const Vec3& up, const Vec3& forward) {
    return glm::dmat4(glm::dvec4(right, 0), glm::dvec4(up, 0), glm::dvec4(forward, 0),
                      glm::dvec4(0, 0, 0, 1));
  };
  switch (face) {
    case CubeFace::kPositiveX:
      return orientation({0, 0, -1}, {0, 1, 0}, {1, 0, 0});
    case CubeFace::kNegativeX:
      return orientation({0, 0, 1}, {0, 1, 0}, {-1, 0, 0});
    case CubeFace::kPositiveY:
      return orientation({1, 0, 0}, {0, 0, -1}, {0, 1, 0});
    case CubeFace::kNegativeY:
      return orientation({1, 0, 0}, {0, 0, 1}, {0, -1, 0});
    case CubeFace::kPositiveZ:
      return orientation({1, 0, 0}, {0, 1, 0}, {0, 0, 1});
    case CubeFace::kNegativeZ:
      return orientation({-1, 0, 0}, {0, 1, 0}, {0, 0, -1});
  }
  return glm::dmat4(1.0);
}

// The face's view sees R at (sc, tc) = (<R, right>, -<R, up>) over ma = <R, forward>
// (t grows downwards); on the projection plane at d = 1 of a 2 x 2 viewport that is
// (sc / ma, -tc / ma) in [-1, 1], which (x + 1) / 2 maps onto [0, 1].
CubeMapPoint CubeMapLookup(const Vec3& R) {
  const Vec3 a = glm::abs(R);
  CubeFace face = R.x >= 0 ? CubeFace::kPositiveX : CubeFace::kNegativeX;
  if (a.y > a.x && a.y >= a.z) {
    face = R.y >= 0 ? CubeFace::kPositiveY : CubeFace::kNegativeY;
  } else if (a.z > a.x && a.z > a.y) {
    face = R.z >= 0 ? CubeFace::kPositiveZ : CubeFace::kNegativeZ;
  }
  const glm::dmat4 view = CubeFaceOrientation(face);
  const double ma = glm::dot(R, Vec3(view[2]));
  const double sc = glm::dot(R, Vec3(view[0]));
  const double tc = -glm::dot(R, Vec3(view[1]));
  return {face, (sc / ma + 1) / 2, (tc / ma + 1) / 2};
}

CubeMap RenderCubeMap(const Scene& scene, const Vec3& centre, int size) {
  Scene surroundings = scene;
  surroundings.viewport = {2, 2, 1};
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
    RenderScene(surroundings, canvas);
    cube_map.faces[static_cast<std::size_t>(f)] = TextureFromImage(canvas.GetImage());
  }
  return cube_map;
}

// Chapter 4, "Reflections".
Vec3 ReflectRay(const Vec3& R, const Vec3& N) {
  return 2.0 * N * glm::dot(N, R) - R;
}

// Pixel (i, j) of a face shows the direction through its centre, (i + 0.5, j + 0.5)
// in texels; GetTexel puts texel (i, j) at the integer point (i, j).
Color SampleCubeMap(const CubeMap& cube_map, const Vec3& R) {
  const CubeMapPoint point = CubeMapLookup(R);
  const Texture& face = cube_map.faces[static_cast<std::size_t>(point.face)];
  return GetTexel(face, point.s * face.width - 0.5, point.t * face.height - 0.5);
}
