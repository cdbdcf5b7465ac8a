#include "clipping.h"

#include <algorithm>
#include <cmath>

// Listing 11-4: put the point in the plane's equation.
double SignedDistance(const Plane& plane, const Vec3& vertex) {
  return glm::dot(vertex, plane.normal) + plane.D;
}

// "Clipping Triangles": <N, A + t(B - A)> + D = 0 gives t = (-D - <N, A>) / <N, B - A>.
// The clipping code only asks this of a segment with one end in front of the plane
// (distance >= 0) and the other behind it (distance < 0), so <N, B - A>, the
// difference of the two distances, is never zero there.
double IntersectionT(const Vec3& A, const Vec3& B, const Plane& plane) {
  return (-plane.D - glm::dot(plane.normal, A)) / glm::dot(plane.normal, B - A);
}

Vec3 Intersection(const Vec3& A, const Vec3& B, const Plane& plane) {
  return A + IntersectionT(A, B, plane) * (B - A);
}

// "The Clipping Volume". With s = 1/sqrt(2), each side plane is at 45 degrees.
// These are wider than the 53-degree view of a 1x1 viewport at d = 1: what survives
// them but falls outside the viewport lands outside the canvas, where PutPixel
// ignores it.
std::vector<Plane> ClippingPlanes(double d) {
  const double s = 1 / std::sqrt(2.0);
  return {
      {{0, 0, 1}, -d},  // near
      {{s, 0, s}, 0},   // left
      {{-s, 0, s}, 0},  // right
      {{0, s, s}, 0},   // bottom
      {{0, -s, s}, 0},  // top
  };
}

// "Clipping Whole Objects".
BoundingSphere ComputeBoundingSphere(const std::vector<Vec3>& vertices) {
  BoundingSphere sphere;
  for (const Vec3& V : vertices) {
    sphere.center += V;
  }
  sphere.center /= static_cast<double>(vertices.size());
  for (const Vec3& V : vertices) {
    sphere.radius = std::max(sphere.radius, glm::length(V - sphere.center));
  }
  return sphere;
}

CameraSpaceInstance TransformToCameraSpace(const Instance& instance, const glm::dmat4& transform) {
  CameraSpaceInstance result;
  result.model = *instance.model;
  for (Vec3& V : result.model.vertices) {
    V = cgfs::ToCartesian(transform * glm::dvec4(V, 1.0));
  }
  // "Shading": normals are directions. They turn with the rotations, are not moved,
  // and are unit vectors again after the (uniform) scale.
  const glm::dmat3 rotation_and_scale(transform);
  for (Triangle& T : result.model.triangles) {
    for (Vec3& N : T.normals) {
      N = glm::normalize(rotation_and_scale * N);
    }
  }
  const BoundingSphere sphere = ComputeBoundingSphere(instance.model->vertices);
  result.bounding_sphere.center = cgfs::ToCartesian(transform * glm::dvec4(sphere.center, 1.0));
  // Rotations and translations keep distances; only the scale changes the radius.
  result.bounding_sphere.radius = sphere.radius * instance.transform.scale;
  return result;
}

// Listing 11-3. A vertex at distance >= 0 counts as in front ("Clipping Triangles":
// a point on the plane is inside the volume). The vertices are relabelled A, B, C
// in the triangle's own cyclic order, so the new triangles keep its winding.
std::vector<Triangle> ClipTriangle(const Triangle& triangle, const Plane& plane,
                                   std::vector<Vec3>& vertices) {
  bool in_front[3];
  int count_in_front = 0;
  for (int i = 0; i < 3; ++i) {
    in_front[i] = SignedDistance(plane, vertices[triangle.v[i]]) >= 0;
    count_in_front += in_front[i];
  }

  if (count_in_front == 3) {
    return {triangle};
  }
  if (count_in_front == 0) {
    return {};
  }

  // A corner of a triangle: a vertex index, and the normal and texture coordinates there.
  struct Corner {
    int vertex;
    Vec3 normal;
    glm::dvec2 uv;
  };
  const auto corner = [&](int k) {
    return Corner{triangle.v[k], triangle.normals[k], triangle.uvs[k]};
  };
  // A new corner where the side from corner a to corner b crosses the plane: a new
  // vertex, and the normal and texture coordinates interpolated with the same t.
  const auto crossing = [&](const Corner& a, const Corner& b) {
    const double t = IntersectionT(vertices[a.vertex], vertices[b.vertex], plane);
    vertices.push_back(Intersection(vertices[a.vertex], vertices[b.vertex], plane));
    return Corner{static_cast<int>(vertices.size()) - 1, a.normal + t * (b.normal - a.normal),
                  a.uv + t * (b.uv - a.uv)};
  };
  const auto make = [&](const Corner& a, const Corner& b, const Corner& c) {
    return Triangle{{a.vertex, b.vertex, c.vertex},
                    triangle.color,
                    {a.normal, b.normal, c.normal},
                    {a.uv, b.uv, c.uv}};
  };

  if (count_in_front == 1) {
    // A is the vertex in front; B and C follow it in the triangle's order.
    const int k = in_front[0] ? 0 : in_front[1] ? 1 : 2;
    const Corner A = corner(k);
    const Corner B = corner((k + 1) % 3);
    const Corner C = corner((k + 2) % 3);
    const Corner B_prime = crossing(A, B);
    const Corner C_prime = crossing(A, C);
    return {make(A, B_prime, C_prime)};
  }

  // Two in front: C is the vertex behind; A and B follow it in the triangle's order.
  const int k = !in_front[0] ? 0 : !in_front[1] ? 1 : 2;
  const Corner C = corner(k);
  const Corner A = corner((k + 1) % 3);
  const Corner B = corner((k + 2) % 3);
  const Corner A_prime = crossing(A, C);
  const Corner B_prime = crossing(B, C);
  return {make(A, B, A_prime), make(A_prime, B, B_prime)};
}

// Listing 11-3. The book writes append(ClipTriangle(...)); the lists are joined.
std::vector<Triangle> ClipTrianglesAgainstPlane(const std::vector<Triangle>& triangles,
                                                const Plane& plane, std::vector<Vec3>& vertices) {
  std::vector<Triangle> clipped_triangles;
  for (const Triangle& T : triangles) {
    const std::vector<Triangle> clipped = ClipTriangle(T, plane, vertices);
    clipped_triangles.insert(clipped_triangles.end(), clipped.begin(), clipped.end());
  }
  return clipped_triangles;
}

// Listing 11-2.
std::optional<CameraSpaceInstance> ClipInstanceAgainstPlane(const CameraSpaceInstance& instance,
                                                            const Plane& plane) {
  const double d = SignedDistance(plane, instance.bounding_sphere.center);
  const double r = instance.bounding_sphere.radius;
  if (d > r) {
    return instance;  // wholly in front
  }
  if (d < -r) {
    return std::nullopt;  // wholly behind
  }
  CameraSpaceInstance clipped_instance = instance;
  clipped_instance.model.triangles =
      ClipTrianglesAgainstPlane(instance.model.triangles, plane, clipped_instance.model.vertices);
  return clipped_instance;
}

// Listing 11-2.
std::optional<CameraSpaceInstance> ClipInstance(const CameraSpaceInstance& instance,
                                                const std::vector<Plane>& planes) {
  std::optional<CameraSpaceInstance> clipped = instance;
  for (const Plane& plane : planes) {
    clipped = ClipInstanceAgainstPlane(*clipped, plane);
    if (!clipped) {
      return std::nullopt;
    }
  }
  return clipped;
}

// Listing 11-1.
CameraSpaceScene ClipScene(const CameraSpaceScene& scene, const std::vector<Plane>& planes) {
  CameraSpaceScene clipped_scene;
  for (const CameraSpaceInstance& I : scene.instances) {
    if (std::optional<CameraSpaceInstance> clipped_instance = ClipInstance(I, planes)) {
      clipped_scene.instances.push_back(*std::move(clipped_instance));
    }
  }
  return clipped_scene;
}
