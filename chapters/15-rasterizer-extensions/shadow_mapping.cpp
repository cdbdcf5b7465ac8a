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

// A map's view is the scene drawn from elsewhere: `seen` (its camera at the light) by
// RenderView, flat, its back faces drawn, into a size x size frame that keeps only the
// depths; the 1/z of each entry, row by row from the top (0: nothing there).
std::vector<double> DrawDepths(const Scene& seen, const std::vector<Plane>& planes, int size) {
  Canvas canvas(size, size);
  DepthBuffer depth_buffer(canvas, DepthValue::kInverseZ);
  DepthOnlyFrame frame(canvas, depth_buffer, seen.viewport);
  Shading flat;
  flat.model = ShadingModel::kFlat;
  PhongSteps none;
  RenderView(seen, planes, flat, {}, frame, none, BackFaces::kDrawn);
  std::vector<double> depths;
  depths.reserve(static_cast<std::size_t>(size) * static_cast<std::size_t>(size));
  for (int y = size / 2 - 1; y >= -size / 2; --y) {
    for (int x = -size / 2; x < size / 2; ++x) {
      depths.push_back(depth_buffer.At(x, y));
    }
  }
  return depths;
}

// A point light's view: a cube map's face seen from the light.
DepthMap PerspectiveView(const Scene& scene, const Vec3& position, CubeFace face, int size) {
  const Viewport viewport = CubeFaceViewport(scene);
  const std::vector<Plane> planes = CubeFaceClippingPlanes(viewport.distance, size);
  const Scene seen = CubeFaceView(scene, position, face, viewport);
  const glm::dmat4 world_to_view = MakeCameraMatrix(position, CubeFaceOrientation(face));
  return {size, DrawDepths(seen, planes, size), world_to_view, false, 1};
}

// A directional light's view: orthographic, a point (x, y, z) of the view at (x, y),
// its depth z linear across the canvas. RenderView draws it as the perspective view
// (d = 1) of the scene moved to (x, y, 1) / w, w = far - z: x d / z gives x back, and
// 1/z, what the depth buffer keeps, is w. The move is projective (the appendix's
// homogeneous (x, y, 1, w)), so triangles stay triangles; w >= 1: nothing to clip.
DepthMap OrthographicView(const Scene& scene, const Vec3& direction, int size) {
  const BoundingSphere bounds = SceneBounds(scene);
  const Vec3 forward = -glm::normalize(direction);
  const glm::dmat4 world_to_view =
      MakeCameraMatrix(bounds.center - forward * (bounds.radius + 1), LookAlong(forward));
  const double far = 2 * bounds.radius + 2;  // the scene lies within 1 <= z <= far - 1
  std::vector<Model> moved;
  for (const CameraSpaceInstance& I : SceneInView(scene, world_to_view).instances) {
    moved.push_back(I.model);
    for (Vec3& vertex : moved.back().vertices) {
      vertex = Vec3(vertex.x, vertex.y, 1) / (far - vertex.z);
    }
  }
  Scene seen;
  seen.viewport = {2 * bounds.radius, 2 * bounds.radius, 1};
  for (const Model& model : moved) {
    seen.instances.push_back({&model, {}});
  }
  std::vector<double> depths = DrawDepths(seen, {}, size);
  for (double& depth : depths) {
    depth = depth > 0 ? far - depth : cgfs::kInf;  // w back to z; 0: nothing there
  }
  return {size, std::move(depths), world_to_view, true, bounds.radius};
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
