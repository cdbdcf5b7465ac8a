// The chapter's own command-line options, which optimisations to use and how many
// threads, and the settings they fill in (see optimizations.h).
#pragma once

#include "optimizations.h"

namespace CLI {
class App;
}

// What the chapter's figures are made with.
struct ChapterSettings {
  Optimizations optimizations = AllOptimizations();
};

// Declares --optimizations and --threads on `app`; once the command line is read, the
// optimisations they name are in `settings`.
void AddChapterOptions(CLI::App& app, ChapterSettings& settings);
