#include "shadow_volumes.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "back_face_culling.h"

bool FacesLight(const Vec3& A, const Vec3& N, const Light& light) {
  switch (light.type) {
    case LightType::kPoint:
      return glm::dot(N, light.position - A) > 0;
    case LightType::kDirectional:
      return glm::dot(N, light.direction) > 0;
    case LightType::kAmbient:
      break;
  }
  return false;
}

namespace {

// For each triangle of the model, whether it faces the light.
std::vector<bool> LightFacing(const Model& model, const Light& light) {
  std::vector<bool> facing;
  for (const Triangle& T : model.triangles) {
    const Vec3& A = model.vertices[T.v[0]];
    const Vec3 N = glm::cross(model.vertices[T.v[1]] - A, model.vertices[T.v[2]] - A);
    facing.push_back(FacesLight(A, N, light));
  }
  return facing;
}

}  // namespace

// In a closed model each edge a -> b of a triangle is the edge b -> a of its
// neighbour. Every edge of a light-facing triangle whose reverse belongs to a
// triangle that does not face the light is on the silhouette.
std::vector<std::array<int, 2>> SilhouetteEdges(const Model& occluder, const Light& light) {
  const std::vector<bool> facing = LightFacing(occluder, light);
  std::map<std::pair<int, int>, bool> edge_faces;  // directed edge -> its triangle faces?
  for (std::size_t t = 0; t < occluder.triangles.size(); ++t) {
    const auto& v = occluder.triangles[t].v;
    for (int k = 0; k < 3; ++k) {
      edge_faces[{v[k], v[(k + 1) % 3]}] = facing[t];
    }
  }
  std::vector<std::array<int, 2>> edges;
  for (std::size_t t = 0; t < occluder.triangles.size(); ++t) {
    if (!facing[t]) {
      continue;
    }
    const auto& v = occluder.triangles[t].v;
    for (int k = 0; k < 3; ++k) {
      const int a = v[k];
      const int b = v[(k + 1) % 3];
      const auto neighbour = edge_faces.find({b, a});
      if (neighbour == edge_faces.end() || !neighbour->second) {
        edges.push_back({a, b});
      }
    }
  }
  return edges;
}

// Vertex i of the occluder is vertex i of the volume, and vertex n + i its image
// pushed away from the light.
Model BuildShadowVolume(const Model& occluder, const Light& light) {
  Model volume;
  volume.closed = true;
  const std::size_t n = occluder.vertices.size();
  volume.vertices = occluder.vertices;
  for (const Vec3& V : occluder.vertices) {
    const Vec3 away = light.type == LightType::kPoint ? V - light.position : -light.direction;
    volume.vertices.push_back(V + glm::normalize(away) * kShadowVolumeLength);
  }
  const int far = static_cast<int>(n);
  const auto add = [&](int a, int b, int c) { volume.triangles.push_back({{a, b, c}}); };
  const std::vector<bool> facing = LightFacing(occluder, light);
  for (std::size_t t = 0; t < occluder.triangles.size(); ++t) {
    if (!facing[t]) {
      const auto [a, b, c] = occluder.triangles[t].v;
      add(a, c, b);                    // near cap: turned over, to face into the occluder
      add(a + far, b + far, c + far);  // far cap: as the occluder has it, away from the light
    }
  }
  // The side on edge a -> b: a, a', b' and a, b', b, which face outwards (away from
  // the light-facing triangle the edge belongs to).
  for (const auto& [a, b] : SilhouetteEdges(occluder, light)) {
    add(a, a + far, b + far);
    add(a, b + far, b);
  }
  return volume;
}

namespace {

// Where ProjectVertex puts v on the canvas, before it truncates to a pixel.
glm::dvec2 CanvasPosition(const Vec3& v, const Canvas& canvas, const Viewport& viewport) {
  return {v.x * viewport.distance / v.z * canvas.Width() / viewport.width,
          v.y * viewport.distance / v.z * canvas.Height() / viewport.height};
}

// Twice the signed area of triangle a, b, p: positive when p is to the left of a -> b
// (y up). Computed the same way for a -> b and b -> a, so that it is exactly the
// negative of itself for the neighbour across an edge.
double EdgeFunction(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& p) {
  const bool swapped = b.x < a.x || (b.x == a.x && b.y < a.y);
  const glm::dvec2& s = swapped ? b : a;
  const glm::dvec2& e = swapped ? a : b;
  const double w = (e.x - s.x) * (p.y - s.y) - (e.y - s.y) * (p.x - s.x);
  return swapped ? -w : w;
}

// Whether a pixel centre exactly on edge a -> b (of a counterclockwise triangle)
// belongs to it: the rule must give each edge to one of the two triangles sharing
// it, or pixels along it would count twice or not at all.
bool OwnsEdge(const glm::dvec2& a, const glm::dvec2& b) {
  return b.y < a.y || (b.y == a.y && b.x > a.x);
}

// The triangle rasterised into the stencil: every pixel whose centre it covers, and
// where the depth test fails (its 1/z is not closer than what the depth buffer holds)
// or passes, as `when_depth_fails` says, gets `delta`.
// Not Listing 7-1: its rows include both ends, so two triangles that share an edge
// both draw the pixels along it, and a count would go up twice. Here pixel (x, y)
// is the point (x + 0.5, y + 0.5), inside a triangle when it is to the left of all
// three sides, and a point on a side belongs to exactly one of the two triangles.
void DrawStencilTriangle(glm::dvec2 p0, glm::dvec2 p1, glm::dvec2 p2, double iz0, double iz1,
                         double iz2, int delta, bool when_depth_fails, const Canvas& canvas,
                         const DepthBuffer& depth_buffer, StencilBuffer& stencil) {
  double area = EdgeFunction(p0, p1, p2);
  if (area == 0) {
    return;  // edge-on: covers no pixel centre
  }
  if (area < 0) {  // make it counterclockwise
    std::swap(p1, p2);
    std::swap(iz1, iz2);
    area = -area;
  }
  const auto covers = [&](double w, const glm::dvec2& a, const glm::dvec2& b) {
    return w > 0 || (w == 0 && OwnsEdge(a, b));
  };
  const int half_w = canvas.Width() / 2;
  const int half_h = canvas.Height() / 2;
  const int y_min = std::max(-half_h, static_cast<int>(std::floor(std::min({p0.y, p1.y, p2.y}))));
  const int y_max = std::min(half_h - 1, static_cast<int>(std::ceil(std::max({p0.y, p1.y, p2.y}))));
  const int x_min = std::max(-half_w, static_cast<int>(std::floor(std::min({p0.x, p1.x, p2.x}))));
  const int x_max = std::min(half_w - 1, static_cast<int>(std::ceil(std::max({p0.x, p1.x, p2.x}))));
  for (int y = y_min; y <= y_max; ++y) {
    // Along the row each edge function is linear in x: find where all three are
    // positive, then check the pixels at the ends exactly.
    double lo = x_min;
    double hi = x_max + 1.0;
    const double py = y + 0.5;
    for (const auto& [a, b] : {std::pair(p1, p2), std::pair(p2, p0), std::pair(p0, p1)}) {
      const double slope = -(b.y - a.y);  // d(EdgeFunction)/dx
      const double at_zero = (b.x - a.x) * (py - a.y) + (b.y - a.y) * a.x;
      if (slope > 0) {
        lo = std::max(lo, -at_zero / slope);
      } else if (slope < 0) {
        hi = std::min(hi, -at_zero / slope);
      } else if (at_zero < 0) {
        hi = lo - 1;
      }
    }
    if (hi < lo) {
      continue;
    }
    const int first = std::max(x_min, static_cast<int>(std::floor(lo - 0.5)) - 1);
    const int last = std::min(x_max, static_cast<int>(std::ceil(hi - 0.5)) + 1);
    for (int x = first; x <= last; ++x) {
      const glm::dvec2 p(x + 0.5, py);
      const double w0 = EdgeFunction(p1, p2, p);
      const double w1 = EdgeFunction(p2, p0, p);
      const double w2 = EdgeFunction(p0, p1, p);
      if (!covers(w0, p1, p2) || !covers(w1, p2, p0) || !covers(w2, p0, p1)) {
        continue;
      }
      // 1/z is linear on the canvas: the corners' values weighted by the areas.
      const double iz = (w0 * iz0 + w1 * iz1 + w2 * iz2) / area;
      if (depth_buffer.Test(x, y, iz) != when_depth_fails) {
        stencil.Add(x, y, delta);
      }
    }
  }
}

}  // namespace

void MarkShadowVolume(const Model& volume, const std::vector<Plane>& clipping_planes,
                      const Canvas& canvas, const Viewport& viewport,
                      const DepthBuffer& depth_buffer, StencilBuffer& stencil,
                      ShadowVolumeCounting counting) {
  const bool depth_fail = counting == ShadowVolumeCounting::kDepthFail;
  std::vector<Vec3> vertices = volume.vertices;
  std::vector<Triangle> triangles = volume.triangles;
  for (const Plane& plane : clipping_planes) {
    triangles = ClipTrianglesAgainstPlane(triangles, plane, vertices);
  }
  const Vec3 camera(0, 0, 0);
  for (const Triangle& T : triangles) {
    const Vec3& A = vertices[T.v[0]];
    const Vec3& B = vertices[T.v[1]];
    const Vec3& C = vertices[T.v[2]];
    const bool back = IsBackFacing(A, B, C, camera);
    const int delta = depth_fail == back ? +1 : -1;
    const glm::dvec2 a = CanvasPosition(A, canvas, viewport);
    const glm::dvec2 b = CanvasPosition(B, canvas, viewport);
    const glm::dvec2 c = CanvasPosition(C, canvas, viewport);
    DrawStencilTriangle(a, b, c, 1 / A.z, 1 / B.z, 1 / C.z, delta, depth_fail, canvas, depth_buffer,
                        stencil);
  }
}
