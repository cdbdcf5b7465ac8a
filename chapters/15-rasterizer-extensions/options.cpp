#include "options.h"

#include <string>

#include "cgfs/arguments.h"
#include "scenes.h"

namespace {

std::string texture_file;

}  // namespace

void AddChapterOptions(CLI::App& app) {
  cgfs::AddTextOption(app, "texture", texture_file,
                      "a PNG, JPEG or PPM image (at most 2048 pixels a side) to paint on the "
                      "crates instead of the project's own crate texture",
                      "FILE");
  cgfs::AfterParsing(app, [] {
    if (!texture_file.empty()) {
      UseCrateTexture(LoadTexture(texture_file));
    }
  });
}
