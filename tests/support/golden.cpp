#include "golden.h"

#include <catch2/catch.hpp>

#include <filesystem>

#include "cgfs/compare.h"
#include "cgfs/error.h"
#include "cgfs/image_io.h"

namespace cgfs::test {

namespace fs = std::filesystem;

const Figure& FindFigure(const std::vector<Figure>& figures, const std::string& name) {
  for (const Figure& figure : figures) {
    if (figure.name == name) {
      return figure;
    }
  }
  FAIL("the chapter's Figures() has no figure named '" << name << "'");
  throw std::logic_error("unreachable");
}

Canvas RenderFigureNamed(const std::vector<Figure>& figures, const std::string& name) {
  return RenderFigure(FindFigure(figures, name), kGoldenWidth, kGoldenHeight);
}

void CheckAgainstGolden(const std::string& chapter, const std::vector<Figure>& figures,
                        const std::string& name) {
  const Image actual = RenderFigureNamed(figures, name).GetImage();
  const fs::path golden = fs::path(CGFS_GOLDEN_DIR) / chapter / (name + ".png");
  INFO("golden image: " << golden.string());
  if (!fs::exists(golden)) {
    FAIL(
        "no golden image; render it with `cmake --build build --target update-golden`, "
        "look at it, and commit it");
  }
  const Comparison comparison = CompareImages(ReadImage(golden), actual);
  if (!comparison.passed) {
    const fs::path folder = fs::path(CGFS_TEST_OUTPUT_DIR) / chapter;
    fs::create_directories(folder);
    const fs::path actual_file = folder / (name + ".actual.png");
    const fs::path difference_file = folder / (name + ".diff.png");
    WriteImage(actual, actual_file);
    WriteImage(comparison.difference, difference_file);
    FAIL(Describe(comparison, actual.Width(), actual.Height())
         << "  actual image:     " << actual_file.string() << "\n"
         << "  difference image: " << difference_file.string()
         << " (" << kDifferenceLegend << ")");
  }
  SUCCEED(Describe(comparison, actual.Width(), actual.Height()));
}

}  // namespace cgfs::test
