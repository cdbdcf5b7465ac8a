// The chapter's own command-line options: how many samples per pixel, the random
// seed, and which optimisations to use (see render.h and optimizations.h); and the
// card's size, 512x512, as the default --size.
#pragma once

namespace CLI {
class App;
}

void AddChapterOptions(CLI::App& app);
