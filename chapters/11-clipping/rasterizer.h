// Chapter 11, "Clipping": the functions of the chapter under the book's names. Where
// the book draws on a global canvas, the function takes it as a last parameter.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include <glm/mat4x4.hpp>

#include "cgfs/canvas.h"
#include "cgfs/color.h"
#include "cgfs/figure.h"
#include "cgfs/math.h"

using cgfs::Canvas;
using cgfs::Color;
using cgfs::Vec3;

// A point on the canvas, in pixels (origin at the centre, y up), with the
// intensity h of the colour there ("Defining Our Problem": 0 black, 1 full colour).
struct Point {
  int x = 0;
  int y = 0;
  double h = 1;
  friend bool operator==(const Point&, const Point&) = default;
};

// "Linear Interpolation": the values d = f(i) of the linear function with
// f(i0) = d0 and f(i1) = d1, for every integer i from i0 to i1 (the value for i is
// at index i - i0). [d0] when i0 == i1, and nothing when i0 > i1.
std::vector<double> Interpolate(int i0, double d0, int i1, double d1);

// Listing 6-2: a segment from P0 to P1 of any slope, in either direction; a single
// pixel when P0 == P1.
void DrawLine(Point P0, Point P1, const Color& color, Canvas& canvas);

// "Drawing Wireframe Triangles": the three sides, with DrawLine.
void DrawWireframeTriangle(Point P0, Point P1, Point P2, const Color& color, Canvas& canvas);

// Listing 7-1: the triangle as a stack of horizontal segments, from the lowest
// vertex to the highest. The vertices may come in any order.
void DrawFilledTriangle(Point P0, Point P1, Point P2, const Color& color, Canvas& canvas);

// Listing 8-1: the filled triangle, its colour scaled by h, which is interpolated
// along the sides like x and then across each row.
void DrawShadedTriangle(Point P0, Point P1, Point P2, const Color& color, Canvas& canvas);

// The viewport: a Vw x Vh window on the projection plane z = d, as in chapter 2.
struct Viewport {
  double width = 1;
  double height = 1;
  double distance = 1;  // d
};

// Listing 9-1: a viewport point (x, y) in canvas pixels, truncated toward zero.
Point ViewportToCanvas(double x, double y, const Canvas& canvas, const Viewport& viewport);

// Listing 9-1, "Finding P'": where the camera at the origin, looking along +Z, sees
// the scene point v on the canvas: (v.x * d / v.z, v.y * d / v.z) on the viewport.
// Only for clipped geometry: clipping against the near plane guarantees v.z >= d.
Point ProjectVertex(const Vec3& v, const Canvas& canvas, const Viewport& viewport);

// "Representing a Cube": a triangle is three indices into its model's vertex list, and a colour.
struct Triangle {
  std::array<int, 3> v{};
  Color color{0, 0, 0};
};

// "Models and Instances": a model is its geometry, in model space.
struct Model {
  std::vector<Vec3> vertices;
  std::vector<Triangle> triangles;
};

// "Model Transform" (Listing 10-4): applied as scale, then rotation, then translation.
struct Transform {
  double scale = 1;
  glm::dmat4 rotation{1.0};
  Vec3 translation{0, 0, 0};
};

// One placement of a model in the scene.
struct Instance {
  const Model* model = nullptr;
  Transform transform;
};

// "Camera Transform": where the camera is, and which way it looks.
struct Camera {
  Vec3 position{0, 0, 0};
  glm::dmat4 orientation{1.0};
};

struct Scene {
  Viewport viewport;
  Camera camera;
  std::vector<Instance> instances;
};

// Listing 10-1: draws a triangle of a model from its projected vertices.
void RenderTriangle(const Triangle& triangle, const std::vector<Point>& projected, Canvas& canvas);

// "The Transform Matrix": I.transform of Listing 10-5, translation * rotation * scale.
glm::dmat4 MakeTransformMatrix(const Transform& transform);

// Listing 10-5: world space to camera space: the inverse of the camera's translation,
// then the inverse of its rotation (a rotation's inverse is its transpose).
glm::dmat4 MakeCameraMatrix(const Vec3& position, const glm::dmat4& orientation);

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

// An instance brought into camera space, what the clipping functions work on:
// its model's vertices and triangles, and its bounding sphere, all transformed.
struct CameraSpaceInstance {
  Model model;
  BoundingSphere bounding_sphere;
};

// Transforms the instance's vertices and its model's bounding sphere by `transform`
// (M_camera * I.transform); the radius grows with the instance's scale.
CameraSpaceInstance TransformToCameraSpace(const Instance& instance, const glm::dmat4& transform);

// Listing 11-3: the triangle if it is wholly in front of the plane, nothing if it is
// wholly behind it, or the one or two triangles that are its part in front. New
// vertices are appended to `vertices`; the winding order of the triangle is kept.
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

// Listing 11-1: the instances that survive clipping, clipped.
std::vector<CameraSpaceInstance> ClipScene(const std::vector<CameraSpaceInstance>& instances,
                                           const std::vector<Plane>& planes);

// Listing 10-5, after clipping: the model's vertices are already in camera space,
// so they are only projected, then every triangle is drawn.
void RenderModel(const Model& model, Canvas& canvas, const Viewport& viewport);

// Every instance into camera space, clipped against the clipping volume, then drawn.
void RenderScene(const Scene& scene, Canvas& canvas);

// The cube of "Representing a Cube": edge 2, centred on the origin, each face two
// triangles of one colour, wound so that (V1 - V0) x (V2 - V0) points outwards.
const Model& CubeModel();

// The scene of Figure 10-10, and the same with a third cube behind the camera.
Scene SceneTransformedCubes();
Scene SceneWithCubeBehindCamera();

// A cube so close to the camera that the near plane cuts it.
Scene SceneCubeCutByNearPlane();

// Every figure this chapter draws.
std::vector<cgfs::Figure> Figures();
