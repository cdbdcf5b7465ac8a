// Chapter 15, "Stencil Shadows" (prose only in the book): the space an occluder
// keeps a light from, built as a closed model, and the stencil buffer counting, for
// every pixel, how many such volumes the point it shows is inside.
#pragma once

#include <array>
#include <vector>

#include "clipping.h"
#include "depth_buffer.h"
#include "stencil_buffer.h"

// "Stencil Shadows": where along the view ray the stencil counts the volumes' faces.
enum class ShadowVolumeCounting {
  kDepthFail,  // behind the surface ("Carmack's reverse"): right wherever the camera is
  kDepthPass,  // in front of it, the first idea: wrong when the camera is in a shadow
};

// Whether a triangle with corner A and normal N faces the light: <N, L> > 0, with L
// from A towards a point light, or a directional light's own direction (as
// "Classifying Triangles" does with the camera). Ambient light faces nothing.
bool FacesLight(const Vec3& A, const Vec3& N, const Light& light);

// The silhouette of a closed model as the light sees it: every edge shared by a
// triangle that faces the light and one that does not, as the pair of vertex indices
// in the order of the light-facing triangle's winding.
std::vector<std::array<int, 2>> SilhouetteEdges(const Model& occluder, const Light& light);

// How far the volume reaches beyond the occluder, away from the light: past every
// scene of the chapter.
inline constexpr double kShadowVolumeLength = 100;

// The shadow volume of a closed occluder (in the same space as the light): the
// space behind it as the light sees it. Closed by the triangles that do not face the
// light, turned over (the near cap), the same triangles pushed kShadowVolumeLength
// away from the light (the far cap), and two triangles on each silhouette edge
// joining the two (the sides); every triangle's (B - A) x (C - A) points out of it,
// as a model's does. The near cap is the occluder's dark side, not its lit side: a
// cap on the lit side would lie exactly on the surfaces the light reaches, and the
// depth test would decide at random, pixel by pixel, whether they are in its shadow.
Model BuildShadowVolume(const Model& occluder, const Light& light);

// The volume's triangles (in camera space) clipped, projected and rasterised into
// the stencil only: each pixel compared with the depth buffer, nothing else written.
// Depth fail ("Carmack's reverse"): where a triangle is behind what the pixel shows
// (the depth test fails), a back face (seen from the camera) adds 1 and a front face
// subtracts 1. Behind a point inside the volume there is one more back face than
// front faces; behind a point outside, as many of each; so the pixels whose stencil
// ends non-zero show points in the shadow, wherever the camera is. Depth pass counts
// in front of the point instead (front +1, back -1): the same, unless the camera is
// inside the volume, whose front face it never crosses.
void MarkShadowVolume(const Model& volume, const std::vector<Plane>& clipping_planes,
                      const Canvas& canvas, const Viewport& viewport,
                      const DepthBuffer& depth_buffer, StencilBuffer& stencil,
                      ShadowVolumeCounting counting = ShadowVolumeCounting::kDepthFail);
