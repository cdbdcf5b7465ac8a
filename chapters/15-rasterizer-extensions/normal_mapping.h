// Chapter 15, "Normal Mapping" (prose only in the book): a texture of normals that
// bends the surface's normal at every pixel, so that a flat triangle lights like a
// bumpy one.
#pragma once

#include <array>

#include <glm/vec2.hpp>

#include "lighting.h"
#include "texture.h"

// A normal map's texel as a vector: each channel c in [0, 255] becomes 2c/255 - 1 in
// [-1, 1]. The map stores normals in tangent space, where x is the direction in which
// u grows on the surface (the tangent), y the one in which v grows (the bitangent)
// and z the surface's own normal; so an unbent normal is (0, 0, 1), stored as
// (128, 128, 255), and normal maps look mostly blue-purple. Not normalised.
Vec3 DecodeNormal(const Color& texel);

// The tangent T and bitangent B of a triangle: the directions on its plane in which
// u and v grow, from its corners P and their (u, v).
struct TangentBasis {
  Vec3 T{1, 0, 0};
  Vec3 B{0, 1, 0};
};

// With E1 = P1 - P0, E2 = P2 - P0 and the differences of u and v along them,
// f = 1 / (du1 dv2 - du2 dv1), T = f (dv2 E1 - dv1 E2), B = f (du1 E2 - du2 E1). A
// triangle whose (u, v) all lie on a line has no such basis: it gets the default.
TangentBasis ComputeTangentBasis(const std::array<Vec3, 3>& P, const std::array<glm::dvec2, 3>& uv);

// The normal map's normal n brought out of tangent space: T and B made perpendicular
// to the unit normal N and to each other, then normalize(T n.x + B n.y + N n.z).
Vec3 ApplyNormalMap(const Vec3& n, const TangentBasis& basis, const Vec3& N);

// The unit normal N bent by `normal_map` at texture coordinates (u, v), if there is a
// map (else N itself). The map is read as a colour texture is, texel (i, j) at the point
// (i, j).
Vec3 BendNormal(const Vec3& N, const Texture* normal_map, const glm::dvec2& uv,
                const TangentBasis& tangents);
