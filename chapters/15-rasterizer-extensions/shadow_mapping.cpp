#include "shadow_mapping.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "depth_buffer.h"
#include "projection.h"
#include "scene_rendering.h"

bool InShadow(double stored_depth, double depth, double bias) {
  return stored_depth < depth - bias;
}

double ShadowBias(const ShadowMapping& settings, double cos_angle) {
  const double sin_angle = std::sqrt(std::max(0.0, 1 - cos_angle * cos_angle));
  const double slope =
      cos_angle * kMaxBiasSlope > sin_angle ? sin_angle / cos_angle : kMaxBiasSlope;
  return settings.constant_bias + settings.slope_bias * slope;
}

double PercentageCloserFilter(const std::array<bool, 4>& in_shadow, double fx, double fy) {
  const std::array<double, 4> weights = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy,
                                         fx * fy};
  double visibility = 0;
  for (std::size_t k = 0; k < 4; ++k) {
    visibility += in_shadow[k] ? 0 : weights[k];
  }
  return visibility;
}

namespace {

// The view's depth at entry (i, j), clamped to the view, as a distance z.
double StoredDepth(const DepthMap& view, int i, int j) {
  i = std::clamp(i, 0, view.size - 1);
  j = std::clamp(j, 0, view.size - 1);
  const double stored =
      view.depths[static_cast<std::size_t>(j) * static_cast<std::size_t>(view.size) +
                  static_cast<std::size_t>(i)];
  return view.orthographic ? stored : 1 / stored;  // 1 / 0: nothing there, infinitely far
}

// Where point P falls on a shadow map: the view, P's depth there, and its place
// (tx, ty) among the entries, entry (i, j) at the point (i, j). A view's (s, t), as a
// cube map's face has them (or, orthographic, scaled from x and y), is at
// (s size, t size - 1), as SampleCubeMap reads a face. Empty if outside every view.
struct ViewPoint {
  const DepthMap* view = nullptr;
  double depth = 0;
  double tx = 0;
  double ty = 0;
};

std::optional<ViewPoint> FindInShadowMap(const ShadowMap& shadow_map, const Vec3& P) {
  if (shadow_map.views.empty()) {
    return std::nullopt;
  }
  const DepthMap* view = &shadow_map.views.front();
  double s = 0;
  double t = 0;
  if (view->orthographic) {
    const Vec3 p = cgfs::ToCartesian(view->world_to_view * glm::dvec4(P, 1.0));
    s = (p.x / view->half_width + 1) / 2;
    t = (-p.y / view->half_width + 1) / 2;
    if (s < 0 || s > 1 || t < 0 || t > 1) {
      return std::nullopt;
    }
  } else {
    const CubeMapPoint point = CubeMapLookup(P - shadow_map.light.position);
    view = &shadow_map.views[static_cast<std::size_t>(point.face)];
    s = point.s;
    t = point.t;
  }
  const double depth = cgfs::ToCartesian(view->world_to_view * glm::dvec4(P, 1.0)).z;
  return ViewPoint{view, depth, s * view->size, t * view->size - 1};
}

// An entry's width at the point: the view's width there over its entries.
double EntryWidth(const ViewPoint& point) {
  const DepthMap& view = *point.view;
  return (view.orthographic ? 2 * view.half_width : 2 * point.depth) / view.size;
}

// The unit vector from P towards the light.
Vec3 TowardsLight(const Light& light, const Vec3& P) {
  return glm::normalize(light.type == LightType::kPoint ? light.position - P : light.direction);
}

// The entry nearest the point: (tx, ty) rounded (StoredDepth clamps it to the view).
std::pair<int, int> NearestEntry(const ViewPoint& point) {
  return {static_cast<int>(std::floor(point.tx + 0.5)),
          static_cast<int>(std::floor(point.ty + 0.5))};
}

}  // namespace

namespace {

// The nearest entry to a point of the map, as one number (ShadowMapEntry).
long EntryNumber(const ShadowMap& shadow_map, const ViewPoint& point) {
  const auto [i, j] = NearestEntry(point);
  const int size = point.view->size;
  const long view = point.view - shadow_map.views.data();
  return (view * size + std::clamp(j, 0, size - 1)) * size + std::clamp(i, 0, size - 1);
}

}  // namespace

std::optional<long> ShadowMapEntry(const ShadowMap& shadow_map, const Vec3& P) {
  const std::optional<ViewPoint> point = FindInShadowMap(shadow_map, P);
  if (!point) {
    return std::nullopt;
  }
  return EntryNumber(shadow_map, *point);
}

double LightVisibility(const ShadowMap& shadow_map, const Vec3& P, const Vec3& N) {
  const std::optional<ViewPoint> point = FindInShadowMap(shadow_map, P);
  if (!point) {
    return 1;
  }
  cgfs::Record(kShadowMapEntries, [&] { return EntryNumber(shadow_map, *point); });
  const ShadowMapping& settings = shadow_map.settings;
  const double cos_angle = glm::dot(N, TowardsLight(shadow_map.light, P));
  const double bias = ShadowBias(settings, cos_angle) * EntryWidth(*point);
  const DepthMap& view = *point->view;
  if (!settings.percentage_closer_filtering) {
    const auto [i, j] = NearestEntry(*point);
    return InShadow(StoredDepth(view, i, j), point->depth, bias) ? 0 : 1;
  }
  const int i = static_cast<int>(std::floor(point->tx));
  const int j = static_cast<int>(std::floor(point->ty));
  const auto shadowed = [&](int di, int dj) {
    return InShadow(StoredDepth(view, i + di, j + dj), point->depth, bias);
  };
  return PercentageCloserFilter({shadowed(0, 0), shadowed(1, 0), shadowed(0, 1), shadowed(1, 1)},
                                point->tx - i, point->ty - j);
}

void LightVisibilities(const Vec3& P, const Vec3& N,
                       const std::vector<const ShadowMap*>& shadow_maps,
                       const glm::dmat4& camera_to_world, std::vector<double>& visibility) {
  visibility.clear();
  if (shadow_maps.empty()) {
    return;
  }
  const Vec3 P_world = cgfs::ToCartesian(camera_to_world * glm::dvec4(P, 1.0));
  const Vec3 N_world = Vec3(camera_to_world * glm::dvec4(N, 0.0));
  for (const ShadowMap* shadow_map : shadow_maps) {
    visibility.push_back(shadow_map ? LightVisibility(*shadow_map, P_world, N_world) : 1.0);
  }
}

namespace {

// The depths a DepthBuffer holds, row by row from the top.
std::vector<double> DepthsOf(const DepthBuffer& depth_buffer, int size) {
  std::vector<double> depths;
  depths.reserve(static_cast<std::size_t>(size) * static_cast<std::size_t>(size));
  for (int y = size / 2 - 1; y >= -size / 2; --y) {
    for (int x = -size / 2; x < size / 2; ++x) {
      depths.push_back(depth_buffer.At(x, y));
    }
  }
  return depths;
}

// The orientation (columns right, up, forward) of a view looking along `forward`.
glm::dmat4 LookAlong(const Vec3& forward) {
  const Vec3 f = glm::normalize(forward);
  const Vec3 helper = std::abs(f.y) < 0.9 ? Vec3(0, 1, 0) : Vec3(1, 0, 0);
  const Vec3 right = glm::normalize(glm::cross(helper, f));
  const Vec3 up = glm::cross(f, right);
  return glm::dmat4(glm::dvec4(right, 0), glm::dvec4(up, 0), glm::dvec4(f, 0),
                    glm::dvec4(0, 0, 0, 1));
}

// A frame that keeps only the depths: a shadow map's view needs no colour.
struct DepthOnlyFrame final : Frame {
  using Frame::Frame;
  void Write(int /*x*/, int /*y*/, const Color& /*color*/) override {}
};

// A point light's view: a cube map's face seen from the light, flat, its back faces
// drawn, into a frame that keeps only the depths.
DepthMap PerspectiveView(const Scene& scene, const Vec3& position, CubeFace face, int size) {
  Canvas canvas(size, size);
  DepthBuffer depth_buffer(canvas, DepthValue::kInverseZ);
  const Viewport viewport = CubeFaceViewport(scene);
  DepthOnlyFrame frame(canvas, depth_buffer, viewport);
  Shading flat;
  flat.model = ShadingModel::kFlat;
  PhongSteps none;
  const Scene seen = CubeFaceView(scene, position, face, viewport);
  const std::vector<Plane> planes = CubeFaceClippingPlanes(viewport.distance, size);
  const glm::dmat4 world_to_view = MakeCameraMatrix(position, CubeFaceOrientation(face));
  RenderView(seen, planes, flat, {}, frame, none, BackFaces::kDrawn);
  return {size, DepthsOf(depth_buffer, size), world_to_view, false, 1};
}

// A directional light's view: orthographic, so a point (x, y, z) of the view's
// space lands at (x, y) scaled to the canvas, whatever its z; z is linear across the
// canvas then, and the depth buffer stores z itself. The view stands beyond the
// scene, so nothing needs clipping. RenderView projects in perspective (ProjectVertex),
// so this view draws its triangles itself, with chapter 12's DrawFilledTriangle.
DepthMap OrthographicView(const Scene& scene, const Vec3& direction, int size) {
  const BoundingSphere bounds = SceneBounds(scene);
  const Vec3 forward = -glm::normalize(direction);
  const glm::dmat4 world_to_view =
      MakeCameraMatrix(bounds.center - forward * (bounds.radius + 1), LookAlong(forward));
  Canvas canvas(size, size);
  const Viewport viewport{2 * bounds.radius, 2 * bounds.radius, 1};
  DepthBuffer depth_buffer(canvas, DepthValue::kZ);
  for (const CameraSpaceInstance& I : SceneInView(scene, world_to_view).instances) {
    const std::vector<Vec3>& V = I.model.vertices;
    std::vector<Point> projected;
    for (const Vec3& vertex : V) {
      projected.push_back(ViewportToCanvas(vertex.x, vertex.y, canvas, viewport));
    }
    for (const Triangle& T : I.model.triangles) {
      DrawFilledTriangle(projected[T.v[0]], projected[T.v[1]], projected[T.v[2]], V[T.v[0]].z,
                         V[T.v[1]].z, V[T.v[2]].z, cgfs::kBlack, canvas, depth_buffer);
    }
  }
  return {size, DepthsOf(depth_buffer, size), world_to_view, true, bounds.radius};
}

}  // namespace

ShadowMap RenderShadowMap(const Scene& scene, const Light& light, const ShadowMapping& settings) {
  ShadowMap shadow_map;
  shadow_map.light = light;
  shadow_map.settings = settings;
  if (light.type == LightType::kPoint) {
    for (int f = 0; f < 6; ++f) {
      shadow_map.views.push_back(
          PerspectiveView(scene, light.position, static_cast<CubeFace>(f), settings.size));
    }
  } else if (light.type == LightType::kDirectional) {
    shadow_map.views.push_back(OrthographicView(scene, light.direction, settings.size));
  }
  return shadow_map;
}
