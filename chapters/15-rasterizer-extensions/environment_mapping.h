// Chapter 15, "Environment Mapping" (prose only in the book): what a reflective
// object would reflect, rendered beforehand as six images around it (a cube map),
// and looked up per pixel in the direction of the reflected ray.
#pragma once

#include <array>

#include <glm/mat4x4.hpp>

#include "cgfs/math.h"
#include "texture.h"

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

// Six square images of the surroundings, indexed by CubeFace.
struct CubeMap {
  std::array<Texture, 6> faces;
};

// Chapter 4's ReflectRay: R reflected about the normal N, 2N<N, R> - R.
Vec3 ReflectRay(const Vec3& R, const Vec3& N);

// The colour the cube map shows in direction R (world space), bilinear. Pixel (i, j)
// of a face, like every canvas's (chapter 1's mapping), shows the direction through
// canvas point (i - S/2, S/2 - 1 - j), which is (s, t) = (i / S, (j + 1) / S) on the
// face; GetTexel puts texel (i, j) at the point (i, j), so (s, t) is read at
// (s S, t S - 1).
Color SampleCubeMap(const CubeMap& cube_map, const Vec3& R);
