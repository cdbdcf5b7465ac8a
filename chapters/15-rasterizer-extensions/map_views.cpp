#include "map_views.h"

#include <cmath>

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

BoundingSphere SceneBounds(const Scene& scene) {
  std::vector<Vec3> everything;
  for (const Instance& I : scene.instances) {
    for (const Vec3& V : I.model->vertices) {
      everything.push_back(ApplyTransform(V, I.transform));
    }
  }
  return ComputeBoundingSphere(everything);
}

double NearPlaneOfMaps(const Scene& scene) {
  return SceneBounds(scene).radius / 1000;
}

std::vector<Plane> CubeFaceClippingPlanes(double d, int size) {
  const double spread = 1 + 4.0 / size;
  const double n = 1 / std::sqrt(1 + spread * spread);
  return {
      {{0, 0, 1}, -d},           // near
      {{n, 0, spread * n}, 0},   // left
      {{-n, 0, spread * n}, 0},  // right
      {{0, n, spread * n}, 0},   // bottom
      {{0, -n, spread * n}, 0},  // top
  };
}

Viewport CubeFaceViewport(const Scene& scene) {
  const double d = NearPlaneOfMaps(scene);
  return {2 * d, 2 * d, d};
}

Scene CubeFaceView(Scene scene, const Vec3& centre, CubeFace face, const Viewport& viewport) {
  scene.camera = {centre, CubeFaceOrientation(face)};
  scene.viewport = viewport;
  return scene;
}
