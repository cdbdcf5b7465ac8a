// The work behind a picture, counted per pixel: what the chapter's optimisations
// save, and where the work still goes. The work is counted where it is done, one line
// at the event (cgfs::Tally: TraceRay's rays, the hierarchy's box and object tests,
// the sampling functions' camera rays); these functions draw with the counting on, for
// one counter at a time. Counts are in memory order (row by row from the top, as the
// canvas stores its pixels), one per pixel.
#pragma once

#include <functional>
#include <vector>

#include "cgfs/tally.h"
#include "raytracer.h"

// Each pixel's count of `counter` while `draw` draws on a canvas of `canvas`'s size.
std::vector<cgfs::Count> CountedPerPixel(const cgfs::Counter& counter, const Canvas& canvas,
                                         const std::function<void()>& draw);

// "Hierarchical Structures", counted: the box tests and the object tests the search
// for the closest hit makes for each pixel's camera ray (ClosestIntersection's
// search, with t from 1: through the hierarchy when `optimizations` ask for it and the
// scene needs one, else one test per object).
struct TestsPerPixel {
  std::vector<cgfs::Count> boxes;
  std::vector<cgfs::Count> objects;
};
TestsPerPixel PrimaryRayTests(const Scene& scene, const Canvas& canvas,
                              const Optimizations& optimizations);

// "Reflections", "Transparency" and "Refraction", counted: the rays TraceRay traces for
// each pixel (kTracedRays), its camera ray and every reflected and refracted ray it
// spawns, with reflections `recursion_depth` deep.
std::vector<cgfs::Count> TracedRays(const Scene& scene, int recursion_depth, const Canvas& canvas,
                                    const Optimizations& optimizations);
