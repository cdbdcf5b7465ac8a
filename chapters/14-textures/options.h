// The chapter's own command-line options, --model FILE and --texture FILE, and the
// settings they fill in: a Wavefront OBJ model of the reader's own, drawn instead of the
// chapter's figures, and the reader's own image on the crates (or on the model) instead
// of the project's (see scenes.h).
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "mipmap.h"
#include "scene.h"
#include "texture.h"

namespace CLI {
class App;
}
namespace cgfs {
struct ModelFile;
}

// What the chapter's figures are made with.
struct ChapterSettings {
  // The reader's model (--model), or none: the chapter's own figures. A model has one
  // texture ("Painting a Crate"): a file's model painted with several is one Model for
  // each (PaintedParts), each with the vertices its triangles use.
  std::shared_ptr<const std::vector<Model>> model;
  std::string model_name;  // its file's name, for the figure's caption
  // The texture on the crates, with its mip chain; none: the project's own.
  std::shared_ptr<const MipmappedTexture> crate_texture;
  // The textures the model's parts are painted with (--texture's among them).
  std::vector<std::shared_ptr<const MipmappedTexture>> model_textures;
};

// Declares --model and --texture on `app`; once the command line is read, the texture (a
// PNG, JPEG or PPM file of at most kMaxTextureSide a side) and the model (read by
// cgfs::ReadModelFile, program/model_file.h) are in `settings`, and what was left out of
// the model has been said in one warning line each. The model is painted with
// --texture's image if there is one, otherwise with its materials' textures (map_Kd).
// A material's texture that cannot be read leaves that material's colour.
void AddChapterOptions(CLI::App& app, ChapterSettings& settings);

// A model file's triangles as the chapter's Model. OBJ's coordinates are right-handed
// and the book's left-handed (the camera looks along +z, x to its right, y up): z is
// negated, which turns the model's front (+z in OBJ) towards the camera, and each
// triangle's corners are listed the other way round, so that (V1 - V0) x (V2 - V0)
// still points outwards. Each triangle has its material's colour (Kd), and at each
// corner the file's normal, or where it gives none (or one of no length) the
// triangle's own ("Normals"). The model is closed ("Back Face Culling") if every edge
// joins exactly two triangles, which go along it in opposite directions: then no back
// face can be seen from outside. The file's texture coordinates, where it gives them,
// are at the corners too, v turned to count down from the top.
Model ModelFromFile(const cgfs::ModelFile& file);

// `model` split into one Model per texture: a triangle's texture is `everywhere` if
// there is one, otherwise its material's, `by_material[material]` (none: its colour).
// Each part keeps only the vertices its triangles use.
std::vector<Model> PaintedParts(Model model, const cgfs::ModelFile& file,
                                const std::vector<const MipmappedTexture*>& by_material,
                                const MipmappedTexture* everywhere);

// The largest texture accepted, a side: 2048 x 2048 texels of 24 bytes are 100 MB,
// and their mip chain a third more.
inline constexpr int kMaxTextureSide = 2048;

// The texels of all a model's textures together (each file counted once, however many
// materials name it): two of the largest, 270 MB with their mip chains. A texture past
// it leaves its materials in their colours.
inline constexpr std::size_t kMaxModelTexels = 2048 * 2048;

// A PNG, JPEG or PPM file as a texture (cgfs::ReadImage). Throws cgfs::Error for a
// file that is not such an image, or one larger than kMaxTextureSide a side (checked
// before any texel is made).
Texture LoadTexture(const std::filesystem::path& path);
