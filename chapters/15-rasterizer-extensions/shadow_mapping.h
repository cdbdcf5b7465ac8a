// Chapter 15, "Shadow Mapping" (prose only in the book): what each light sees,
// rendered beforehand as depths, so that shading a point can ask whether something
// is closer to the light than it is: the maps made, and read.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include <glm/mat4x4.hpp>

#include "cgfs/tally.h"
#include "lighting.h"
#include "map_views.h"

// How the shading reads a shadow map.
struct ShadowMapping {
  int size = 256;  // entries per side of each view
  // The bias: how much closer to the light the map must hold something before a point
  // counts as shadowed, in entry widths at the point's distance from the light. Each
  // entry holds the depth of the surface at the entry's centre; a point elsewhere in
  // the entry, on a surface that slopes away from the light at an angle a (between its
  // normal and the light), lies up to (its distance from the centre) x tan(a) deeper.
  // Without a bias the surface shadows itself in streaks ("shadow acne"), worst where
  // the light grazes it, where tan(a) is large; so the bias has a constant part and a
  // part that grows with tan(a) (slope-scaled), the slope capped at kMaxBiasSlope. Too
  // much bias and shadows start a little away from the objects casting them
  // ("peter-panning").
  double constant_bias = 1;
  double slope_bias = 2;
  // Percentage-closer filtering: the comparison made with the four entries around
  // the point and the results weighted as GetTexel weighs texels, so that
  // visibility goes from 0 to 1 across a shadow's edge instead of jumping.
  bool percentage_closer_filtering = false;
};

// The steepest slope the bias allows for: 10, an angle of 84 degrees between the
// normal and the light.
inline constexpr double kMaxBiasSlope = 10;

// One view from a light: the depth of the nearest surface at each of size x size
// entries, row by row from the top, entry (i, j) the canvas pixel (i - size/2,
// size/2 - 1 - j) of the view's render. A point light's views are perspective (90
// degrees, like a cube map's faces) and store 1/z; a directional light's view is
// orthographic (parallel to the light) and stores z.
struct DepthMap {
  int size = 0;
  std::vector<double> depths;
  glm::dmat4 world_to_view{1.0};  // world space to the view's camera space
  bool orthographic = false;
  double half_width = 1;  // orthographic: the view covers x and y in [-half_width, half_width]
};

// All a light's views: six for a point light (indexed by CubeFace), one for a
// directional light, none for ambient light; and how they are read.
struct ShadowMap {
  std::vector<DepthMap> views;
  Light light;  // in world space
  ShadowMapping settings;
};

// The comparison: a point `depth` away from the light is in shadow when the map
// holds something closer, by more than `bias`.
bool InShadow(double stored_depth, double depth, double bias);

// The bias at a point whose normal makes an angle with the light whose cosine is
// `cos_angle`, in entry widths (ShadowMapping).
double ShadowBias(const ShadowMapping& settings, double cos_angle);

// Percentage-closer filtering of four comparisons (in shadow or not) of the entries
// top-left, top-right, bottom-left and bottom-right of a point, fx and fy its
// position between them: the fraction of the light that reaches the point.
double PercentageCloserFilter(const std::array<bool, 4>& in_shadow, double fx, double fy);

// How much of the light whose shadow map this is reaches world-space point P of a
// surface whose unit normal there is N, in [0, 1]: 0 or 1, or in between with
// filtering. Points outside every view are lit. The entry the lookup reads is recorded
// at the pixel being drawn (kShadowMapEntries), for the cost view of the map's
// resolution.
double LightVisibility(const ShadowMap& shadow_map, const Vec3& P, const Vec3& N);

// The entry a lookup without filtering reads for world-space point P (the one nearest
// the point), as one number: view x size x size + row x size + column; empty for a point
// outside every view. The number LightVisibility records; declared here so that the
// tests can hold the cost view's entries against an independent ray caster, which
// reaches the map only through this header.
std::optional<long> ShadowMapEntry(const ShadowMap& shadow_map, const Vec3& P);
inline constexpr cgfs::Counter kShadowMapEntries{"shadow-map entries read"};

// "Shadow Mapping", at a point of the camera's view: how much of each light reaches
// camera-space point P, whose unit normal is N, into `visibility`, one per shadow map
// (nullptr for a light without one); nothing when there are no maps. The maps are in
// world space: camera_to_world takes P and N there.
void LightVisibilities(const Vec3& P, const Vec3& N,
                       const std::vector<const ShadowMap*>& shadow_maps,
                       const glm::dmat4& camera_to_world, std::vector<double>& visibility);

// "Shadow Mapping": the scene's depths as `light` (in world space) sees them,
// settings.size x settings.size per view: six perspective views from a point light, one
// orthographic view along a directional light, covering a sphere around every
// instance's vertices and seen from beyond it; none for ambient light. No back faces
// are culled: a surface that faces away from the light casts a shadow too.
ShadowMap RenderShadowMap(const Scene& scene, const Light& light, const ShadowMapping& settings);
