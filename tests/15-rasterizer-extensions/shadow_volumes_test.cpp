// Chapter 15, "Stencil Shadows": silhouettes, volumes, and counting in the stencil.
#include <catch2/catch.hpp>

#include <map>
#include <utility>

#include "scenes.h"
#include "shadow_volumes.h"
#include "sphere_model.h"

namespace {

// Every directed edge a -> b of a closed, consistently wound model is matched by
// exactly one b -> a.
bool IsClosed(const Model& model) {
  std::map<std::pair<int, int>, int> edges;
  for (const Triangle& T : model.triangles) {
    for (int k = 0; k < 3; ++k) {
      ++edges[{T.v[k], T.v[(k + 1) % 3]}];
    }
  }
  for (const auto& [edge, count] : edges) {
    const auto reverse = edges.find({edge.second, edge.first});
    if (count != 1 || reverse == edges.end() || reverse->second != 1) {
      return false;
    }
  }
  return true;
}

// A box around the view axis, x and y in [-1, 1], z from z_near to z_far: the cube of
// "Representing a Cube" stretched, wound outwards as it is.
Model Box(double z_near, double z_far) {
  Model box = CubeModel();
  for (Vec3& V : box.vertices) {
    V.z = V.z < 0 ? z_near : z_far;
  }
  return box;
}

// The stencil at the centre of a 20 x 20 canvas after counting the box's faces,
// where the visible surface is everywhere at depth z_surface.
int CountAtCentre(const Model& box, double z_surface, ShadowVolumeCounting counting) {
  Canvas canvas(20, 20);
  const Viewport viewport;
  DepthBuffer depth_buffer(canvas, DepthValue::kInverseZ);
  for (int y = -10; y < 10; ++y) {
    for (int x = -10; x < 10; ++x) {
      depth_buffer.TestAndSet(x, y, 1 / z_surface);
    }
  }
  StencilBuffer stencil(canvas);
  MarkShadowVolume(box, ClippingPlanes(viewport.distance), canvas, viewport, depth_buffer, stencil,
                   counting);
  return stencil.At(0, 0);
}

}  // namespace

TEST_CASE("a cube lit head-on has the four edges of its lit face as its silhouette",
          "[shadow-volumes]") {
  const Light light{LightType::kDirectional, 1, {}, {0, 0, -1}};  // the light is towards -z
  const auto edges = SilhouetteEdges(CubeModel(), light);
  REQUIRE(edges.size() == 4);
  for (const auto& [a, b] : edges) {
    CHECK(CubeModel().vertices[a].z == -1);
    CHECK(CubeModel().vertices[b].z == -1);
  }
  CHECK(FacesLight({0, 0, -1}, {0, 0, -1}, light));
  CHECK_FALSE(FacesLight({1, 0, 0}, {1, 0, 0}, light));  // edge-on faces nothing
  CHECK(FacesLight({0, 0, -1}, {0, 0, -1}, {LightType::kPoint, 1, {0, 0, -5}}));
  CHECK_FALSE(FacesLight({0, 0, -1}, {0, 0, -1}, {LightType::kAmbient, 1}));
}

TEST_CASE("shadow volumes are closed and face outwards", "[shadow-volumes]") {
  const Light directional{LightType::kDirectional, 1, {}, {0, 0, -1}};
  const Model volume = BuildShadowVolume(CubeModel(), directional);
  CHECK(IsClosed(volume));
  // Its signed volume, the sum of (A x B) . C / 6 over its triangles, is positive
  // only if they face outwards. The region is the cube's dark side (its top at
  // z = +1; its sides, edge-on to the light, sweep nothing) swept 100 away: 2 x 2 x 100.
  double signed_volume = 0;
  for (const Triangle& T : volume.triangles) {
    signed_volume += glm::dot(glm::cross(volume.vertices[T.v[0]], volume.vertices[T.v[1]]),
                              volume.vertices[T.v[2]]) /
                     6;
  }
  CHECK(signed_volume == Approx(2 * 2 * kShadowVolumeLength));
  // A point light that sees three faces.
  CHECK(IsClosed(BuildShadowVolume(CubeModel(), {LightType::kPoint, 1, {3, 4, -5}})));
  // GenerateSphere's poles are rings of coincident vertices: strictly, two holes of
  // no area, which change no count (the figures' sphere casts a whole shadow).
  const Model sphere = GenerateSphere(15, cgfs::kGreen);
  CHECK_FALSE(IsClosed(sphere));
}

TEST_CASE("depth fail: a surface inside the volume is in shadow, outside it is not",
          "[shadow-volumes]") {
  using enum ShadowVolumeCounting;
  const Model volume = Box(4, 8);
  CHECK(CountAtCentre(volume, 6, kDepthFail) == 1);   // (a) inside: the back face fails
  CHECK(CountAtCentre(volume, 3, kDepthFail) == 0);   // (b) nearer: both fail, +1 -1
  CHECK(CountAtCentre(volume, 10, kDepthFail) == 0);  // (c) beyond: both pass
  // Depth pass agrees while the camera is outside.
  CHECK(CountAtCentre(volume, 6, kDepthPass) == 1);
  CHECK(CountAtCentre(volume, 3, kDepthPass) == 0);
  CHECK(CountAtCentre(volume, 10, kDepthPass) == 0);
}

TEST_CASE("depth fail is right with the camera inside the volume, depth pass is not",
          "[shadow-volumes]") {
  using enum ShadowVolumeCounting;
  const Model volume = Box(-2, 8);                    // the camera, at the origin, is inside
  CHECK(CountAtCentre(volume, 6, kDepthFail) == 1);   // (a) inside: in shadow
  CHECK(CountAtCentre(volume, 10, kDepthFail) == 0);  // (c) beyond: lit
  // Depth pass never sees the front face (it is behind the camera, clipped away).
  CHECK(CountAtCentre(volume, 6, kDepthPass) == 0);
  CHECK(CountAtCentre(volume, 10, kDepthPass) == -1);
}

TEST_CASE("the stencil buffer counts per pixel and clears", "[shadow-volumes]") {
  Canvas canvas(4, 4);
  StencilBuffer stencil(canvas);
  stencil.Add(-2, 1, 1);
  stencil.Add(-2, 1, 1);
  stencil.Add(1, -2, -1);
  stencil.Add(5, 5, 1);  // off the canvas: ignored
  CHECK(stencil.At(-2, 1) == 2);
  CHECK(stencil.At(1, -2) == -1);
  CHECK(stencil.At(0, 0) == 0);
  CHECK(stencil.At(5, 5) == 0);
  stencil.Clear();
  CHECK(stencil.At(-2, 1) == 0);
}

TEST_CASE("the stencil buffer's cells are the canvas's pixels, corners included",
          "[shadow-volumes]") {
  // A 4 x 2 canvas: x in [-2, 1], y in [-1, 0]. Each corner is its own cell, and a point
  // just off any edge is no cell at all.
  Canvas canvas(4, 2);
  StencilBuffer stencil(canvas);
  stencil.Add(-2, -1, 1);
  stencil.Add(1, -1, 2);
  stencil.Add(-2, 0, 3);
  stencil.Add(1, 0, 4);
  CHECK(stencil.At(-2, -1) == 1);
  CHECK(stencil.At(1, -1) == 2);
  CHECK(stencil.At(-2, 0) == 3);
  CHECK(stencil.At(1, 0) == 4);
  for (const auto& [x, y] : {std::pair{2, 0}, {-3, 0}, {0, 1}, {0, -2}}) {
    stencil.Add(x, y, 9);
    CHECK(stencil.At(x, y) == 0);
  }
  CHECK(stencil.At(0, 0) == 0);
  CHECK(stencil.At(-1, -1) == 0);
}
