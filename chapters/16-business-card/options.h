// The chapter's own command-line options, the samples per pixel, the random seed and
// the optimisations (see render.h and optimizations.h), and the settings they fill in;
// and the card's size, 512x512, as the default --size.
#pragma once

#include "render.h"

namespace CLI {
class App;
}

inline constexpr std::uint32_t kDefaultSeed = 1;

// What the chapter's figures are made with: the card's samples, seed and optimisations,
// 64, 1 and all of them unless the command line says otherwise.
struct ChapterSettings {
  RenderSettings card{kCardSamples, kDefaultSeed, AllOptimizations()};
};

// Declares --samples, --seed, --optimizations and --threads on `app`; once the command
// line is read, what they give is in `settings`.
void AddChapterOptions(CLI::App& app, ChapterSettings& settings);
