#include "options.h"

#include <memory>
#include <string>

#include "program/arguments.h"
#include "program/error.h"
#include "program/image_files.h"

void AddChapterOptions(CLI::App& app, ChapterSettings& settings) {
  auto file = std::make_shared<std::string>();
  cgfs::AddTextOption(app, "texture", *file,
                      "a PNG, JPEG or PPM image (at most 2048 pixels a side) to paint on the "
                      "crates instead of the project's own crate texture",
                      "FILE");
  cgfs::AfterParsing(app, [file, &settings] {
    if (!file->empty()) {
      settings.crate_texture =
          std::make_shared<const MipmappedTexture>(BuildMipChain(LoadTexture(*file)));
    }
  });
}

Texture LoadTexture(const std::filesystem::path& path) {
  const cgfs::Image image = cgfs::ReadImage(path);
  if (image.Width() > kMaxTextureSide || image.Height() > kMaxTextureSide) {
    throw cgfs::Error("'" + path.string() + "' is " + std::to_string(image.Width()) + "x" +
                      std::to_string(image.Height()) + ", too large for a texture (at most " +
                      std::to_string(kMaxTextureSide) + " a side)");
  }
  return TextureFromImage(image);
}
