// ShowFigures in a build without SDL2 (cmake found no libsdl2-dev): one line saying how
// to get it; every chapter still builds and draws its files.
#include "program/error.h"
#include "program/window.h"

namespace cgfs {

void ShowFigures(const std::string&, const std::vector<const Figure*>&, int, int,
                 const std::filesystem::path&, const std::string&, const View&) {
  throw UsageError(
      "--window needs SDL2, which this build did not find: install libsdl2-dev (scripts/setup "
      "does) and build again");
}

}  // namespace cgfs
