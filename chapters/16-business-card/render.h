// The card's main(): every pixel, the average of many samples through a lens.
#pragma once

#include <cstdint>

#include "camera.h"
#include "cgfs/canvas.h"
#include "optimizations.h"
#include "sample.h"

inline constexpr int kCardSamples = 64;
// The stratified card's samples per pixel: the fewest with less noise than the card's
// 64 independent ones (README.md, "Fewer samples, placed better").
inline constexpr int kStratifiedSamples = 28;

struct RenderSettings {
  int samples = kCardSamples;  // per pixel
  std::uint32_t seed = 1;      // the image's seed (random.h)
  Optimizations optimizations;
  // Low-discrepancy samples instead of the card's independent ones: sample i's point in
  // the pixel, on the lens and on the light (for the first thing it hits) are the i-th
  // point of a Sobol sequence scrambled for the pixel, which spreads the samples
  // evenly where independent ones leave gaps and clusters: the same mean, less noise
  // for as many samples.
  bool stratified = false;
};

// The value of pixel (x, y) in the card's pixel coordinates: x from 0 at the image's
// right to width − 1 at its left, y from 0 at the bottom to height − 1 at the top.
// Each of the `samples` samples, with random numbers in this order:
//   - a point t on the lens, t = a·(R − ½)·aperture + b·(R − ½)·aperture;
//   - a point in the pixel, (x + R, y + R);
//   - the ray from the eye moved to t, aimed at the pixel's point kFocus along the
//     pixel ray: everything at that distance is sharp, the rest blurred (depth of
//     field), and the point in the pixel smooths the edges;
//   - its Sample, times 3.5.
// The card adds them to 13 (a dark base): 13 + 224·mean. Returned truncated to a
// whole number, as the card prints them, and clamped to 0..255 (the card cannot
// exceed it in this scene; its brightest channel is about 232).
glm::ivec3 RenderPixel(const Camera& camera, int x, int y, const RenderSettings& settings);

// Draws the card on the canvas: every pixel of it, each from its own generator
// (random.h), on the threads the settings ask for, from the card's eye moved as `view`
// asks (MakeCamera). Reports its progress.
void Render(cgfs::Canvas& canvas, const RenderSettings& settings, const cgfs::View& view = {});
