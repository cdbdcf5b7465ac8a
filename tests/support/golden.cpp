#include "golden.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <map>
#include <system_error>
#include <tuple>

#include "comparison/compare.h"
#include "program/error.h"
#include "program/image_files.h"
#include "report.h"

namespace cgfs::test {

namespace fs = std::filesystem;

namespace {

// <build>/test-output/report.html: every figure whose golden test failed last time it
// ran, side by side with ours (tools/report.h); no page at all once none has.
void UpdateReport(const fs::path& output) {
  const std::vector<ReportEntry> entries = CompareFolder(output, CGFS_GOLDEN_DIR, false);
  if (entries.empty()) {
    std::error_code ignored;
    fs::remove(output / "report.html", ignored);
    return;
  }
  WriteReport(entries, output / "report.html", "Golden tests that failed");
}

}  // namespace

const Figure& FindFigure(const std::vector<Figure>& figures, const std::string& name) {
  for (const Figure& figure : figures) {
    if (figure.name == name) {
      return figure;
    }
  }
  FAIL("the chapter's Figures() has no figure named '" << name << "'");
  throw std::logic_error("unreachable");
}

namespace {

// Each figure is drawn once per test program and size, and the golden test and the
// tests of its pixels share the drawing: within a test program a figure's name stands
// for one image (every caller passes the chapter's Figures() with its default
// settings; that other settings draw the same images is tested with RenderFigure).
struct Drawing {
  Canvas canvas;
  std::string measured;  // what the figure said it measured once drawn
};
const Drawing& DrawnOnce(const Figure& figure, int width, int height) {
  static std::map<std::tuple<std::string, int, int>, Drawing> drawn;
  const auto key = std::tuple(figure.name, width, height);
  auto found = drawn.find(key);
  if (found == drawn.end()) {
    Canvas canvas = RenderFigure(figure, width, height);
    found = drawn.emplace(key, Drawing{std::move(canvas), figure.measured ? figure.measured() : ""})
                .first;
  }
  return found->second;
}

}  // namespace

Canvas RenderFigureNamed(const std::vector<Figure>& figures, const std::string& name) {
  return DrawnOnce(FindFigure(figures, name), kGoldenWidth, kGoldenHeight).canvas;
}

std::string MeasuredByFigureNamed(const std::vector<Figure>& figures, const std::string& name) {
  return DrawnOnce(FindFigure(figures, name), kGoldenWidth, kGoldenHeight).measured;
}

std::string GoldenFile(const std::string& chapter, const std::string& name) {
  return (fs::path(CGFS_GOLDEN_DIR) / chapter / (name + ".png")).string();
}

namespace {

// The golden image of the figure; a test failure if there is none.
Image ReadGolden(const std::string& chapter, const std::string& name) {
  const fs::path golden = GoldenFile(chapter, name);
  INFO("golden image: " << golden.string());
  if (!fs::exists(golden)) {
    FAIL(
        "no golden image; render it with `cmake --build build --target update-golden`, "
        "look at it, and commit it");
  }
  return ReadImage(golden);
}

void CompareWithGolden(const std::string& chapter, const std::string& name, const Image& golden,
                       const Image& actual) {
  INFO("golden image: " << GoldenFile(chapter, name));
  const Comparison comparison = CompareImages(golden, actual);
  const fs::path output = CGFS_TEST_OUTPUT_DIR;
  const fs::path folder = output / chapter;
  const fs::path actual_file = folder / (name + ".png");
  const fs::path difference_file = folder / (name + ".diff.png");
  if (!comparison.passed) {
    fs::create_directories(folder);
    WriteImage(actual, actual_file);
    WriteImage(comparison.difference, difference_file);
    UpdateReport(output);
    FAIL(Describe(comparison, actual.Width(), actual.Height())
         << "  actual image:     " << actual_file.string() << "\n"
         << "  difference image: " << difference_file.string() << " (" << DifferenceLegend()
         << ")\n"
         << "  every failed figure side by side: " << (output / "report.html").string());
  }
  // A pass clears what an earlier failure of this figure left behind.
  std::error_code error;
  const bool stale = fs::remove(actual_file, error);
  fs::remove(difference_file, error);
  if (stale) {
    UpdateReport(output);
  }
  SUCCEED(Describe(comparison, actual.Width(), actual.Height()));
}

}  // namespace

void CheckAgainstGolden(const std::string& chapter, const std::vector<Figure>& figures,
                        const std::string& name) {
  const Image golden = ReadGolden(chapter, name);
  const Figure& figure = FindFigure(figures, name);
  CompareWithGolden(chapter, name, golden,
                    DrawnOnce(figure, golden.Width(), golden.Height()).canvas.GetImage());
}

void CheckImageAgainstGolden(const std::string& chapter, const std::string& name,
                             const Image& actual) {
  CompareWithGolden(chapter, name, ReadGolden(chapter, name), actual);
}

}  // namespace cgfs::test
