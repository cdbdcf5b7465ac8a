#include "options.h"

#include <memory>
#include <string>

#include "cgfs/arguments.h"

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
