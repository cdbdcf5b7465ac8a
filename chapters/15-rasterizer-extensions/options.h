// The chapter's own command-line option, --texture FILE, and the settings it fills in:
// the reader's own image on the crates instead of the project's (see scenes.h).
#pragma once

#include <filesystem>
#include <memory>

#include "mipmap.h"
#include "texture.h"

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

// The largest texture accepted, a side: 2048 x 2048 texels of 24 bytes are 100 MB,
// and their mip chain a third more.
inline constexpr int kMaxTextureSide = 2048;

// A PNG, JPEG or PPM file as a texture (cgfs::ReadImage). Throws cgfs::Error for a
// file that is not such an image, or one larger than kMaxTextureSide a side (checked
// before any texel is made).
Texture LoadTexture(const std::filesystem::path& path);
