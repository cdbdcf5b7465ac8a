// The chapter's own command-line options, --model FILE (a model of the reader's own,
// drawn instead of the chapter's figures) and --texture FILE (an image of the reader's
// own on the crates, or on the model: scenes.h), and the settings they fill in.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "mipmap.h"
#include "program/arguments.h"
#include "program/book_model.h"
#include "scene.h"

// What the chapter's figures are made with.
struct ChapterSettings {
  // The reader's model (--model), or none: the chapter's own figures. A Model has one
  // texture ("Painting a Crate"): a model painted with several is one Model for each.
  std::shared_ptr<const std::vector<Model>> model;
  std::string model_name;  // its file's name, for the figure's caption
  // The texture on the crates, with its mip chain; none: the project's own.
  std::shared_ptr<const MipmappedTexture> crate_texture;
  // The textures the model's parts are painted with, but --texture's (crate_texture).
  std::vector<std::shared_ptr<const MipmappedTexture>> model_textures;
};

// Declares --model and --texture on `app`; once the command line is read, the texture
// (cgfs::ReadTextureImage) and the model (ReadBookModel, which says what it left out)
// are in `settings`. The model is painted with --texture's image if there is one,
// otherwise with its materials' (cgfs::MaterialImages, cgfs::PaintedParts).
void AddChapterOptions(CLI::App& app, ChapterSettings& settings);

// A model file in the book's coordinates as the chapter's Model: each triangle in its
// material's colour (Kd), with a normal and texture coordinates at each corner, closed
// if the file's surface is ("Back Face Culling").
Model ModelFromFile(const cgfs::BookModel& file);

// The largest texture, a side (2048 x 2048 texels of 24 bytes, 100 MB, and a third more
// for its mip chain), and a model's textures together: two of the largest (past it,
// materials keep their colours).
inline constexpr int kMaxTextureSide = 2048;
inline constexpr std::size_t kMaxModelTexels = 2048 * 2048;
