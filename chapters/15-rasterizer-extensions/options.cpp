#include "options.h"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace {

std::shared_ptr<const MipmappedTexture> MipmappedTextureOf(const cgfs::Image& image) {
  return std::make_shared<const MipmappedTexture>(BuildMipChain(TextureFromImage(image)));
}

// The model's parts, one per texture (cgfs::PaintedParts: --texture's, the crate's, on
// all of it if given), each texture made with its mip chain and kept in `settings`.
void PaintModel(const cgfs::BookModel& model, const std::string& name,
                const std::shared_ptr<const cgfs::Image>& crate, ChapterSettings& settings) {
  auto parts = std::make_shared<std::vector<Model>>();
  const auto by_material =
      cgfs::MaterialImages(model.materials, name, kMaxTextureSide, kMaxModelTexels);
  for (const cgfs::PaintedPart& part : cgfs::PaintedParts(model, by_material, crate)) {
    std::shared_ptr<const MipmappedTexture> texture = settings.crate_texture;
    if (!crate && part.texture) {
      texture = MipmappedTextureOf(*part.texture);
      settings.model_textures.push_back(texture);
    }
    parts->push_back(ModelFromFile(part.model));
    parts->back().texture = texture.get();
  }
  settings.model = std::move(parts);
}

}  // namespace

void AddChapterOptions(CLI::App& app, ChapterSettings& settings) {
  auto file = std::make_shared<std::string>();
  auto texture_file = std::make_shared<std::string>();
  cgfs::AddModelOption(app, *file, "the figure 'model'");
  cgfs::AddTextOption(app, "texture", *texture_file,
                      "a PNG, JPEG or PPM image (at most 2048 pixels a side) to paint on the "
                      "crates, or on the model, instead of the project's own crate texture",
                      "FILE");
  cgfs::AfterParsing(app, [file, texture_file, &settings] {
    std::shared_ptr<const cgfs::Image> crate;
    if (!texture_file->empty()) {
      crate = std::make_shared<const cgfs::Image>(
          cgfs::ReadTextureImage(*texture_file, kMaxTextureSide));
      settings.crate_texture = MipmappedTextureOf(*crate);
    }
    if (!file->empty()) {
      PaintModel(cgfs::ReadBookModel(*file), *file, crate, settings);
      settings.model_name = std::filesystem::path(*file).filename().string();
    }
  });
}

Model ModelFromFile(const cgfs::BookModel& file) {
  Model model{file.vertices, {}, file.closed};
  for (const cgfs::BookModel::Triangle& T : file.triangles) {
    model.triangles.push_back({T.v, T.color, T.normals, T.uvs});
  }
  return model;
}
