// The chapter's own command-line options: which optimisations to use, and how many
// threads (see optimizations.h).
#pragma once

namespace CLI {
class App;
}

void AddChapterOptions(CLI::App& app);
