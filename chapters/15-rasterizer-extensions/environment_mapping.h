// Chapter 15, "Environment Mapping" (prose only in the book): what a reflective
// object would reflect, rendered beforehand as six images around it (a cube map),
// and looked up per pixel in the direction of the reflected ray.
#pragma once

#include <array>

#include <glm/mat4x4.hpp>

#include "cgfs/math.h"
#include "map_views.h"
#include "scene.h"
#include "texture.h"

// Six square images of the surroundings, indexed by CubeFace.
struct CubeMap {
  std::array<Texture, 6> faces;
};

// Chapter 4's ReflectRay: R reflected about the normal N, 2N<N, R> - R.
Vec3 ReflectRay(const Vec3& R, const Vec3& N);

// "Environment Mapping" at a pixel: its colour with its reflection mixed in, as chapter 4
// mixes in the reflected ray's: (1 - r) local + r SampleCubeMap(R), R = 2N<N, V> - V
// turned into world space (camera_to_world) for a surface that reflects r of its
// `environment` (none, or r = 0: the colour as it is). The reflection is added in the
// first pass only, as the ambient light is; a later pass still scales the local colour
// by 1 - r.
Color MixReflection(const Color& local, const Vec3& P, const Vec3& N, const CubeMap* environment,
                    double reflective, bool first_pass, const glm::dmat4& camera_to_world);

// The colour the cube map shows in direction R (world space), bilinear. Pixel (i, j)
// of a face, like every canvas's (chapter 1's mapping), shows the direction through
// canvas point (i - S/2, S/2 - 1 - j), which is (s, t) = (i / S, (j + 1) / S) on the
// face; GetTexel puts texel (i, j) at the point (i, j), so (s, t) is read at
// (s S, t S - 1).
Color SampleCubeMap(const CubeMap& cube_map, const Vec3& R);

// "Environment Mapping": the surroundings seen from `centre`, six 90-degree views
// (viewport 2d x 2d at d = NearPlaneOfMaps), size x size pixels each: the scene's
// instances that reflect nothing, drawn by RenderView (scene_rendering.h) with the
// default (Phong) shading and no stage, so reflections show no shadows. The
// reflective ones are left out: each would otherwise have to be in the others' maps,
// and its own map is made from inside it. The map is centred on the reflective
// object, not on the room as the book suggests: with one object, its centre is where
// the reflection is least wrong.
CubeMap RenderCubeMap(const Scene& scene, const Vec3& centre, int size);
