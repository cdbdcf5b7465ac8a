// Chapter 13, "Shading" begins with chapter 3's "Light": light sources and the
// illumination equation, now for the rasterizer. Everything here works in camera
// space, where the camera is at the origin.
#pragma once

#include <span>
#include <vector>

#include <glm/mat4x4.hpp>

#include "cgfs/math.h"

using cgfs::Vec3;

// Chapter 3, "Light Sources". All light is white, so a light is one intensity.
enum class LightType { kAmbient, kPoint, kDirectional };

struct Light {
  LightType type = LightType::kAmbient;
  double intensity = 0;
  Vec3 position{0, 0, 0};   // point lights
  Vec3 direction{0, 0, 0};  // directional lights: the direction towards the light, L itself
};

// Which terms of the illumination equation to add up (the ambient term always is):
// the chapter's figures show diffuse alone, specular alone, and both.
struct LightingTerms {
  bool diffuse = true;
  bool specular = true;
};

// Chapter 3's ComputeLighting (Listings 3-1 and 3-2): the light at point P with unit
// normal N, seen along V (from P towards the camera), for a surface of specular
// exponent s (-1: matte). P, N, V and the lights must be in the same space.
// "Shadow Mapping": `visibility`, if not empty, has for each light the fraction of it
// that reaches P (as chapter 4's shadow rays decide, 0 or 1).
double ComputeLighting(const Vec3& P, const Vec3& N, const Vec3& V, double s,
                       const std::vector<Light>& lights, const LightingTerms& terms = {},
                       std::span<const double> visibility = {});

// "Shading": the lights brought into camera space with the camera matrix, like the
// vertices: a point light's position as a point, a directional light's direction as
// a direction (rotated, not moved).
std::vector<Light> TransformLights(const std::vector<Light>& lights, const glm::dmat4& M_camera);
