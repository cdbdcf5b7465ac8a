// The chapter's own command-line option, --texture FILE, and the settings it fills in:
// the reader's own image on the crates instead of the project's (see scenes.h).
#pragma once

#include <memory>

#include "mipmap.h"

namespace CLI {
class App;
}

// What the chapter's figures are made with.
struct ChapterSettings {
  // The texture on the crates, with its mip chain; none: the project's own.
  std::shared_ptr<const MipmappedTexture> crate_texture;
};

// Declares --texture on `app`; once the command line is read, the texture (a PNG, JPEG
// or PPM file of at most kMaxTextureSide a side) is loaded into `settings`.
void AddChapterOptions(CLI::App& app, ChapterSettings& settings);
