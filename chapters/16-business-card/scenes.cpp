#include "scenes.h"

#include <string>

#include "optimizations.h"

int& ChosenSamples() {
  static int samples = kCardSamples;
  return samples;
}

std::uint32_t& ChosenSeed() {
  static std::uint32_t seed = kDefaultSeed;
  return seed;
}

namespace {

// The card with `samples` per pixel, and the seed and optimisations of the command line.
void DrawCard(cgfs::Canvas& canvas, int samples) {
  RenderSettings settings;
  settings.samples = samples;
  settings.seed = ChosenSeed();
  settings.optimizations = ChosenOptimizations();
  Render(canvas, settings);
}

}  // namespace

std::vector<cgfs::Figure> Figures() {
  return {
      {"business-card",
       "the card's image: \"aek\" in mirror spheres, " + std::to_string(ChosenSamples()) +
           " samples per pixel",
       [](cgfs::Canvas& canvas) { DrawCard(canvas, ChosenSamples()); }},
      {"business-card-1-sample", "one sample per pixel: why the card takes 64",
       [](cgfs::Canvas& canvas) { DrawCard(canvas, 1); }},
  };
}
