// Chapter 10, "Describing and Rendering a Scene": the functions of the chapter under the
// book's names. Where
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
// Until chapter 11 clips against the near plane, a point in front of the
// projection plane (v.z < d, the camera's own plane and behind it included) has
// no place on the canvas: nothing is returned for it.
std::optional<Point> ProjectVertex(const Vec3& v, const Canvas& canvas, const Viewport& viewport);

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

// Listing 10-1: draws a triangle of a model from its projected vertices. A
// triangle with a vertex that could not be projected (see ProjectVertex) is
// skipped whole until chapter 11 clips it.
void RenderTriangle(const Triangle& triangle, const std::vector<std::optional<Point>>& projected,
                    Canvas& canvas);

// Listing 10-1: projects every vertex once (each is shared by several
// triangles), then draws every triangle as a wireframe.
void RenderObject(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles,
                  Canvas& canvas, const Viewport& viewport);

// Listing 10-4: the vertex scaled, then rotated, then translated.
Vec3 ApplyTransform(const Vec3& vertex, const Transform& transform);

// Listing 10-3: an instance, each vertex transformed into the scene by
// ApplyTransform; the camera stays at the origin looking along +Z.
void RenderInstance(const Instance& instance, Canvas& canvas, const Viewport& viewport);

// "The Transform Matrix": I.transform of Listing 10-5, translation * rotation * scale.
glm::dmat4 MakeTransformMatrix(const Transform& transform);

// Listing 10-5: world space to camera space: the inverse of the camera's translation,
// then the inverse of its rotation (a rotation's inverse is its transpose).
glm::dmat4 MakeCameraMatrix(const Vec3& position, const glm::dmat4& orientation);

// Listing 10-5: every vertex through one matrix, projected, then every triangle drawn.
void RenderModel(const Model& model, const glm::dmat4& transform, Canvas& canvas,
                 const Viewport& viewport);

// Listing 10-5: every instance, seen from the scene's camera.
void RenderScene(const Scene& scene, Canvas& canvas);

// The cube of "Representing a Cube": edge 2, centred on the origin, each face two
// triangles of one colour, wound so that (V1 - V0) x (V2 - V0) points outwards.
const Model& CubeModel();

// The scenes of Figures 10-3 and 10-10.
Scene SceneTwoCubes();
Scene SceneTransformedCubes();

// Every figure this chapter draws.
std::vector<cgfs::Figure> Figures();
