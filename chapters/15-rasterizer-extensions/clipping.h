// Chapter 11, "Clipping": the clipping volume, and clipping at the level of whole
// instances, of triangles and of vertices, under the book's names.
#pragma once

#include <optional>
#include <vector>

#include "scene.h"

// "The Clipping Volume": the plane of points P with <N, P> + D = 0. N has unit
// length and points into the volume, so <N, P> + D is P's signed distance.
struct Plane {
  Vec3 normal{0, 0, 0};
  double D = 0;
};

// Listing 11-4.
double SignedDistance(const Plane& plane, const Vec3& vertex);

// "Clipping Triangles": the t at which the segment A + t(B - A) crosses the plane.
// Any attribute of the vertices (an intensity, a normal, ...) is interpolated with
// the same t: a_Q = a_A + t(a_B - a_A).
double IntersectionT(const Vec3& A, const Vec3& B, const Plane& plane);

// "Clipping Triangles": the point where the segment AB crosses the plane.
Vec3 Intersection(const Vec3& A, const Vec3& B, const Plane& plane);

// "The Clipping Volume" (Figure 11-2): the near plane z = d and four planes through
// the camera at 45 degrees, a 90-degree field of view.
std::vector<Plane> ClippingPlanes(double d);

// "Clipping Whole Objects": a sphere that contains the whole model.
struct BoundingSphere {
  Vec3 center{0, 0, 0};
  double radius = 0;
};

// The book's rough method: the centre is the average of the vertices, the radius
// the distance from it to the farthest vertex.
BoundingSphere ComputeBoundingSphere(const std::vector<Vec3>& vertices);

// An instance brought into camera space, what the clipping functions work on: its
// model's vertices and triangles, and its bounding sphere, all transformed. Clipping
// changes them, so each instance has its own copy of the model.
struct CameraSpaceInstance {
  Model model;
  BoundingSphere bounding_sphere;
};

// The scene as the clipping functions see it: every instance in camera space.
struct CameraSpaceScene {
  std::vector<CameraSpaceInstance> instances;
};

// Transforms the instance's vertices and its model's bounding sphere by `transform`
// (M_camera * I.transform); the radius grows with the instance's scale,
// and the triangles' normals turn with it.
CameraSpaceInstance TransformToCameraSpace(const Instance& instance, const glm::dmat4& transform);

// Listing 11-3: the triangle if it is wholly in front of the plane, nothing if it is
// wholly behind it, or the one or two triangles that are its part in front. New
// vertices are appended to `vertices`; the winding order of the triangle is kept.
// The normals and texture coordinates at the new corners are interpolated like the
// positions.
std::vector<Triangle> ClipTriangle(const Triangle& triangle, const Plane& plane,
                                   std::vector<Vec3>& vertices);

// Listing 11-3: every triangle clipped, the results joined in one list.
std::vector<Triangle> ClipTrianglesAgainstPlane(const std::vector<Triangle>& triangles,
                                                const Plane& plane, std::vector<Vec3>& vertices);

// Listing 11-2: the instance unchanged if its bounding sphere is wholly in front of
// the plane, nothing if wholly behind, otherwise a copy with its triangles clipped.
std::optional<CameraSpaceInstance> ClipInstanceAgainstPlane(const CameraSpaceInstance& instance,
                                                            const Plane& plane);

// Listing 11-2: clipped against each plane in turn; nothing once a plane rejects it.
std::optional<CameraSpaceInstance> ClipInstance(const CameraSpaceInstance& instance,
                                                const std::vector<Plane>& planes);

// Listing 11-1: a copy of the scene with the instances that survive clipping, clipped.
CameraSpaceScene ClipScene(const CameraSpaceScene& scene, const std::vector<Plane>& planes);
