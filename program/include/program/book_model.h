// A model file (model_file.h) in the book's coordinates: the one conversion behind every
// chapter's --model. Each chapter copies it into its own Model in a few lines
// (options.cpp).
#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "cgfs/image.h"
#include "program/model_file.h"

namespace cgfs {

// OBJ's coordinates are right-handed and the book's left-handed (the camera looks along
// +z, x to its right, y up): z is negated, which turns the model's front (+z in OBJ)
// towards the camera, and each triangle's corners are listed the other way round, so
// that (V1 - V0) x (V2 - V0) still points outwards. At each corner: the file's normal,
// or where it gives none (or one of no length) the triangle's own, unit length
// ("Normals"); the file's texture coordinates, v turned to count down from the top of
// the image as the book's textures do ((0, 0) where it gives none). Each triangle has
// its material's colour (Kd). The model is closed ("Back Face Culling") if every edge
// joins exactly two triangles, which go along it in opposite directions: then no back
// face can be seen from outside.
struct BookModel {
  struct Triangle {
    std::array<int, 3> v{};  // indices into vertices
    glm::dvec3 color{0, 0, 0};
    std::array<glm::dvec3, 3> normals{};
    std::array<glm::dvec2, 3> uvs{};
    int material = -1;  // index into the file's materials; -1: none
  };
  std::vector<glm::dvec3> vertices;
  std::vector<Triangle> triangles;
  bool closed = false;
  std::vector<ModelFile::Material> materials;  // the file's
};

BookModel InBookCoordinates(const ModelFile& file);

// Reads a model file (ReadModelFile, which throws cgfs::Error with one line for a file
// it cannot use), says what was left out of it in one warning line each (Warn), and
// converts it.
BookModel ReadBookModel(const std::filesystem::path& path);

// The model split into `parts` models, triangle t into part part_of[t]; each part keeps
// only the vertices its triangles use (numbered anew, in the order they are first
// used) and the model's closedness (a back face of a closed surface cannot be seen,
// whichever part it is in), not its materials (each triangle keeps its index into the
// model's). Its memory beyond the parts' own is one number per vertex of the model,
// however many parts there are (up to kMaxMaterials, each on up to kMaxModelVertices).
std::vector<BookModel> SplitModel(const BookModel& model, const std::vector<std::size_t>& part_of,
                                  std::size_t parts);

// A PNG, JPEG or PPM file (ReadImage) to be used as a texture. Throws cgfs::Error for a
// file that is not such an image, or one larger than `max_side` a side (checked before
// any texel is made).
Image ReadTextureImage(const std::filesystem::path& path, int max_side);

// Each material's texture (map_Kd) as an image, or none where it has none, it cannot be
// read (ReadTextureImage), or it would take the model's textures past `max_texels`
// together. A file is read once, by its real path, however many materials name it (they
// share its image); each file left out is said in one warning (Warn), with how many
// materials name it, `name` naming the model.
std::vector<std::shared_ptr<const Image>> MaterialImages(
    const std::vector<ModelFile::Material>& materials, const std::string& name, int max_side,
    std::size_t max_texels);

// A part of a model with one texture ("Painting a Crate" paints a model with one): its
// triangles and the image painted on them, or none (their colours).
struct PaintedPart {
  BookModel model;
  std::shared_ptr<const Image> texture;
};

// The model split into one part per texture (SplitModel), in the order the textures
// first appear: a triangle's texture is `everywhere` if given, otherwise its material's,
// by_material[material] (MaterialImages; none: its colour).
std::vector<PaintedPart> PaintedParts(const BookModel& model,
                                      const std::vector<std::shared_ptr<const Image>>& by_material,
                                      const std::shared_ptr<const Image>& everywhere);

}  // namespace cgfs
