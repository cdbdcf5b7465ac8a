// The chapter's own command-line options, --model FILE and --texture FILE, and the
// settings they fill in: a Wavefront OBJ model of the reader's own, drawn instead of the
// chapter's figures, and the reader's own image on the crates (or on the model) instead
// of the project's (see scenes.h).
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "mipmap.h"
#include "scene.h"

namespace CLI {
class App;
}
namespace cgfs {
struct BookModel;
}

// What the chapter's figures are made with.
struct ChapterSettings {
  // The reader's model (--model), or none: the chapter's own figures. A model has one
  // texture ("Painting a Crate"): a file's model painted with several is one Model for
  // each (cgfs::PaintedParts), each with the vertices its triangles use.
  std::shared_ptr<const std::vector<Model>> model;
  std::string model_name;  // its file's name, for the figure's caption
  // The texture on the crates, with its mip chain; none: the project's own.
  std::shared_ptr<const MipmappedTexture> crate_texture;
  // The textures the model's parts are painted with, but --texture's (crate_texture).
  std::vector<std::shared_ptr<const MipmappedTexture>> model_textures;
};

// Declares --model and --texture on `app`; once the command line is read, the texture (a
// PNG, JPEG or PPM file of at most kMaxTextureSide a side) and the model (read by
// cgfs::ReadBookModel, program/book_model.h) are in `settings`, and what was left out of
// the model has been said in one warning line each. The model is painted with
// --texture's image if there is one, otherwise with its materials' textures (map_Kd,
// cgfs::MaterialImages). A material's texture that cannot be read leaves that
// material's colour.
void AddChapterOptions(CLI::App& app, ChapterSettings& settings);

// A model file, in the book's coordinates (cgfs::InBookCoordinates), as the chapter's
// Model: each triangle in its material's colour (Kd), with a normal and texture
// coordinates at each corner, the model closed if the file's surface is ("Back Face
// Culling").
Model ModelFromFile(const cgfs::BookModel& file);

// The largest texture accepted, a side: 2048 x 2048 texels of 24 bytes are 100 MB,
// and their mip chain a third more.
inline constexpr int kMaxTextureSide = 2048;

// The texels of all a model's textures together (each file counted once, however many
// materials name it): two of the largest, 270 MB with their mip chains. A texture past
// it leaves its materials in their colours.
inline constexpr std::size_t kMaxModelTexels = 2048 * 2048;
