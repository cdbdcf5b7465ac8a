// Chapter 15, "Shadow Mapping" (prose only in the book): what each light sees,
// rendered beforehand as depths, so that shading a point can ask whether something
// is closer to the light than it is.
#pragma once

#include <vector>

#include <glm/mat4x4.hpp>

#include "environment_mapping.h"
#include "lighting.h"

struct Scene;

// One view from a light: the depth of the nearest surface at each of size x size
// entries, row by row from the top. A point light's views are perspective (90
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
// directional light, none for ambient light.
struct ShadowMap {
  std::vector<DepthMap> views;
  Vec3 light_position{0, 0, 0};  // a point light's
};

// The scene's depths as `light` (in world space) sees them, size x size per view.
// A directional light's single view covers a sphere around every instance's
// vertices, seen from beyond it.
ShadowMap RenderShadowMap(const Scene& scene, const Light& light, int size);

// The comparison: a point `depth` away from the light is in shadow when the map
// holds something closer, by more than `bias`. The bias allows for the map's own
// errors: the surface a point lies on was stored at the depth of the entry's centre,
// which on a slope is a little closer or farther than the point itself, and
// without the bias the surface would shadow itself in stripes ("shadow acne").
bool InShadow(double stored_depth, double depth, double bias);

// How the shading reads a shadow map.
struct ShadowMapping {
  int size = 256;  // entries per side of each view
  // The bias, in entry widths at the point's distance from the light: each entry
  // holds the depth at its centre, and a surface sloping away from the light is
  // (entry width) x (slope) deeper elsewhere in the entry. Too small a bias: acne;
  // too large: shadows that start a little away from the objects casting them
  // ("peter-panning"). See LightVisibility.
  double bias = 1.5;
  // Percentage-closer filtering: the comparison made with the four entries around
  // the point and the results weighted as GetTexel weighs texels (chapter 14), so
  // that visibility goes from 0 to 1 across a shadow's edge instead of jumping.
  bool percentage_closer_filtering = false;
};

// Percentage-closer filtering of four comparisons (in shadow or not) of the entries
// top-left, top-right, bottom-left and bottom-right of a point, fx and fy its
// position between them: the fraction of the light that reaches the point.
double PercentageCloserFilter(const std::array<bool, 4>& in_shadow, double fx, double fy);

// How much of the light whose shadow map this is reaches world-space point P of a
// surface whose unit normal there is N, in [0, 1]: 0 or 1, or in between with
// filtering. Points outside every view are lit.
double LightVisibility(const ShadowMap& shadow_map, const Vec3& P, const Vec3& N,
                       const ShadowMapping& settings);
