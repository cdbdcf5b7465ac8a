#include "options.h"

#include <CLI/CLI.hpp>

#include <string>

#include "scenes.h"

namespace {

std::string texture_file;

}  // namespace

void AddChapterOptions(CLI::App& app) {
  app.add_option("--texture", texture_file,
                 "a PNG, JPEG or PPM image (at most 2048 pixels a side) to paint on the crates "
                 "instead of the project's own crate texture")
      ->type_name("FILE");
  app.final_callback([] {
    if (!texture_file.empty()) {
      UseCrateTexture(LoadTexture(texture_file));
    }
  });
}
