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

std::vector<cgfs::Figure> Figures() {
  return {
      {"business-card",
       "the card's image: \"aek\" in mirror spheres, " + std::to_string(ChosenSamples()) +
           " samples per pixel",
       [](cgfs::Canvas& canvas) {
         RenderSettings settings;
         settings.samples = ChosenSamples();
         settings.seed = ChosenSeed();
         settings.optimizations = ChosenOptimizations();
         Render(canvas, settings);
       }},
      {"business-card-1-sample", "one sample per pixel: why the card takes 64",
       [](cgfs::Canvas& canvas) {
         RenderSettings settings;
         settings.samples = 1;
         settings.seed = ChosenSeed();
         settings.optimizations = ChosenOptimizations();
         Render(canvas, settings);
       }},
  };
}
