// The chapter's own command-line options (samples per pixel, the random seed, the
// optimisations: render.h, optimizations.h), the settings they fill in, the card's size.
#pragma once

#include "program/arguments.h"
#include "render.h"

inline constexpr std::uint32_t kDefaultSeed = 1;

// What the chapter's figures are made with: the card's samples, seed and optimisations,
// 64, 1 and all of them unless the command line says otherwise.
struct ChapterSettings {
  RenderSettings card{kCardSamples, kDefaultSeed, AllOptimizations()};
};

// Declares --samples, --seed, --optimizations and --threads on `app`; once the command
// line is read, what they give is in `settings`.
void AddChapterOptions(CLI::App& app, ChapterSettings& settings);
