// Chapter 15: the views the maps are rendered from. A cube map's faces, and a point
// light's shadow map, are six 90-degree views from a point inside the scene, one along
// each axis; a directional light's is one view from beyond the scene. Both kinds must
// see all of the scene, however close to their centre a part of it is.
#pragma once

#include <vector>

#include <glm/mat4x4.hpp>

#include "cgfs/math.h"
#include "clipping.h"
#include "scene.h"

using cgfs::Vec3;

// The six faces of a cube map, each a 90-degree view along one axis.
enum class CubeFace { kPositiveX, kNegativeX, kPositiveY, kNegativeY, kPositiveZ, kNegativeZ };

// The camera orientation (as in chapter 10: columns right, up, forward) of each
// face's view. Each face is seen without mirroring: right x up = forward.
glm::dmat4 CubeFaceOrientation(CubeFace face);

// Where direction R meets the cube: the face of its largest component (by absolute
// value, and its sign), and the point (s, t) on that face, both in [0, 1], s to the
// right and t down as in a texture: s = (sc / |ma| + 1) / 2, t = (tc / |ma| + 1) / 2,
// with ma the largest component and sc, tc the two others as that face's view sees
// them (the usual cube-map layout).
struct CubeMapPoint {
  CubeFace face = CubeFace::kPositiveZ;
  double s = 0.5;
  double t = 0.5;
};
CubeMapPoint CubeMapLookup(const Vec3& R);

// A sphere around every vertex of every instance, in world space: what a map's views
// must see.
BoundingSphere SceneBounds(const Scene& scene);

// The near plane of the views rendered for the maps: a thousandth of the radius of
// SceneBounds, so that nothing of the scene is cut away however close to a view's
// centre it is.
double NearPlaneOfMaps(const Scene& scene);

// The clipping volume of a cube map's face of size x size pixels, or of a shadow map's
// view from a point light (the same 90-degree view, viewport 2d x 2d): the near plane
// z = d, and side planes opened two pixels beyond the face's edges, through the
// points where |x| / z or |y| / z = 1 + 4 / size, so that the rasteriser, which
// truncates toward zero, does not leave the edge columns and rows of the face empty.
std::vector<Plane> CubeFaceClippingPlanes(double d, int size);

// The viewport of a cube map's face, or of a view of a point light's shadow map: 2d x 2d
// at d = NearPlaneOfMaps, a 90-degree view.
Viewport CubeFaceViewport(const Scene& scene);

// A cube map's face, or a view of a point light's shadow map: `scene` with its camera at
// `centre`, looking along `face`, and `viewport` (CubeFaceViewport). RenderView
// (scene_rendering.h) draws it through CubeFaceClippingPlanes into a square canvas
// behind a 1/z depth buffer.
Scene CubeFaceView(Scene scene, const Vec3& centre, CubeFace face, const Viewport& viewport);
