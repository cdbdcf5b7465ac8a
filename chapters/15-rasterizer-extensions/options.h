// The chapter's own command-line option: --texture FILE, the reader's own image on the
// crates instead of the project's (see scenes.h).
#pragma once

namespace CLI {
class App;
}

void AddChapterOptions(CLI::App& app);
