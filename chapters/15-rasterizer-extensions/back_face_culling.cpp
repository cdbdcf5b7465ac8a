#include "back_face_culling.h"

#include <algorithm>

// "Classifying Triangles".
bool IsBackFacing(const Vec3& A, const Vec3& B, const Vec3& C, const Vec3& camera) {
  const Vec3 V1 = B - A;
  const Vec3 V2 = C - A;
  const Vec3 N = glm::cross(V1, V2);
  const Vec3 V = camera - A;
  return glm::dot(N, V) <= 0;
}

// Listing 12-1.
void CullBackFaces(Model& object, const Vec3& camera) {
  std::erase_if(object.triangles, [&](const Triangle& T) {
    return IsBackFacing(object.vertices[T.v[0]], object.vertices[T.v[1]], object.vertices[T.v[2]],
                        camera);
  });
}
