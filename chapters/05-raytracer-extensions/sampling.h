// Fewer rays than pixels ("Subsampling") and more ("Supersampling").
#pragma once

#include "cgfs/tally.h"
#include "raytracer.h"

// "Subsampling", a main loop of its own beside RenderScene: traces the pixels with
// even coordinates, then, for each pixel in between, when the traced pixels on both
// sides (all four around, for a pixel in the middle of a square) hit the same object,
// only that object is intersected, and when they all saw the background, so does the
// pixel. Everywhere else the pixel is traced. Approximate: an object thinner than two
// pixels can vanish. With the other optimisations chosen.
void RenderSceneSubsampled(const Scene& scene, int recursion_depth, Canvas& canvas,
                           const Optimizations& optimizations);

// The main loop the optimisations choose: RenderSceneSubsampled when they ask for
// subsampling, else RenderScene (what --optimizations does to every figure).
void RenderSceneAsChosen(const Scene& scene, int recursion_depth, Canvas& canvas,
                         const Optimizations& optimizations);

// "Supersampling": n x n rays per pixel on a regular grid centred on the pixel's own
// ray, each colour clamped to 0..255 and then averaged, drawn with the chosen
// optimisations (subsampling aside). n = 1 is RenderScene.
void RenderSceneSupersampled(const Scene& scene, int recursion_depth, int n, Canvas& canvas,
                             const Optimizations& optimizations);

// The adaptive variant: one ray per pixel, then 4 x 4 rays only for the pixels
// whose ray hits another object than a neighbour's, or whose colour differs from a
// neighbour's by more than kAdaptiveThreshold in a channel. Returns how many pixels
// were subdivided.
inline constexpr double kAdaptiveThreshold = 24;
cgfs::Count RenderSceneAdaptive(const Scene& scene, int recursion_depth, Canvas& canvas,
                                const Optimizations& optimizations);

// The camera rays these functions search the whole scene with, counted (a cost view,
// cost.h): subsampling's traced pixels and those whose neighbours disagree, each
// sample of supersampling.
inline constexpr cgfs::Counter kCameraRays{"camera rays"};
