// The work behind a picture, counted per pixel: what the chapter's optimisations
// save, and where the work still goes. Counts are in memory order (row by row from the
// top, as the canvas stores its pixels), one per pixel.
#pragma once

#include <vector>

#include "raytracer.h"

// "Hierarchical Structures", counted: the box tests and the object tests the search
// for the closest hit makes for each pixel's camera ray (ClosestIntersection's
// search, with t from 1: through the hierarchy when `optimizations` ask for it and the
// scene needs one, else one test per object).
struct TestsPerPixel {
  std::vector<long> boxes;
  std::vector<long> objects;
};
TestsPerPixel PrimaryRayTests(const Scene& scene, const Canvas& canvas,
                              const Optimizations& optimizations);

// "Reflections", "Transparency" and "Refraction", counted: the rays TraceRay traces for
// each pixel, its camera ray and every reflected and refracted ray it spawns, with
// reflections `recursion_depth` deep (Scene::traced_rays). One thread.
std::vector<long> TracedRays(const Scene& scene, int recursion_depth, const Canvas& canvas,
                             const Optimizations& optimizations);

// The index of canvas pixel (x, y) in memory order: what counts per pixel are stored by.
inline std::size_t PixelIndex(int x, int y, const Canvas& canvas) {
  const cgfs::ScreenPoint screen = *canvas.ToScreen(x, y);
  return static_cast<std::size_t>(screen.row) * static_cast<std::size_t>(canvas.Width()) +
         static_cast<std::size_t>(screen.column);
}
