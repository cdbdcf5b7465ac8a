// A chapter's figures for its web page (scripts/site): compiled to WebAssembly with the
// chapter's own code, in place of main.cpp. The page asks for a figure by its index and
// a size, and copies the pixels it gets (RGBA, as ImageData holds them) into its
// canvas; the camera of a figure that has one moves as in the window
// (program/camera_controls.h). A request that cannot be met returns 0 and leaves one
// line in LastError() for the page to show. A chapter with options of its own
// (options.h) reads them from the page as its program reads them from a command line
// (UseOptions): a model the reader chose is drawn by the chapter's own code.
// This file alone of program/ stands above the chapters: it is the web programs'
// main.cpp, compiled into each chapter's web program with that chapter's files (which is
// why it can include scenes.h), never into the web shell library the chapters stand on.
#include <emscripten.h>

#include <algorithm>
#include <cstdint>
#include <exception>
#include <string>
#include <string_view>
#include <vector>

#include "comparison/compare.h"
#include "program/camera_controls.h"
#include "program/figure.h"
#include "scenes.h"
#if __has_include("options.h")
#include "options.h"
#include "web_options.h"
#endif

namespace {

// The figures: made, when first asked for, with the settings a command line without
// options gives; made anew by UseOptions.
std::vector<cgfs::Figure> chapter_figures;
bool figures_made = false;

const std::vector<cgfs::Figure>& ChapterFigures() {
  if (!figures_made) {
#if __has_include("options.h")
    chapter_figures = Figures(ChapterSettings{});
#else
    chapter_figures = Figures();
#endif
    figures_made = true;
  }
  return chapter_figures;
}

cgfs::View view;                   // the camera's view, for the figures that have one
cgfs::Comparison comparison;       // the last comparison of a reader's image with a figure
std::vector<std::uint8_t> pixels;  // the last figure drawn, RGBA
std::string text;                  // what the last call that returns text returned
std::string last_error;

const cgfs::Figure* FigureAt(int index) {
  const auto& figures = ChapterFigures();
  if (index < 0 || index >= static_cast<int>(figures.size())) {
    last_error = "there is no figure " + std::to_string(index) + " (this chapter has " +
                 std::to_string(figures.size()) + ")";
    return nullptr;
  }
  return &figures[static_cast<std::size_t>(index)];
}

const char* Text(std::string value) {
  text = std::move(value);
  return text.c_str();
}

// An image's RGB bytes into `pixels` as RGBA, opaque, as a canvas's ImageData holds them.
void KeepAsRgba(const std::vector<std::uint8_t>& rgb) {
  pixels.resize(rgb.size() / 3 * 4);
  for (std::size_t from = 0, to = 0; from < rgb.size(); from += 3, to += 4) {
    pixels[to] = rgb[from];
    pixels[to + 1] = rgb[from + 1];
    pixels[to + 2] = rgb[from + 2];
    pixels[to + 3] = 255;
  }
}

}  // namespace

extern "C" {

EMSCRIPTEN_KEEPALIVE const char* ChapterName() {
  return CGFS_CHAPTER;
}
EMSCRIPTEN_KEEPALIVE const char* ChapterDescription() {
  return kChapterDescription;
}
EMSCRIPTEN_KEEPALIVE int FigureCount() {
  return static_cast<int>(ChapterFigures().size());
}

// The figure's name, its caption, and whether it has a camera to move (1) or not (0);
// an index out of range gives "" and -1.
EMSCRIPTEN_KEEPALIVE const char* FigureName(int index) {
  const cgfs::Figure* figure = FigureAt(index);
  return Text(figure != nullptr ? figure->name : "");
}
EMSCRIPTEN_KEEPALIVE const char* FigureCaption(int index) {
  const cgfs::Figure* figure = FigureAt(index);
  return Text(figure != nullptr ? figure->caption : "");
}
// What the figure's last draw measured (a cost view's totals), "" when nothing.
EMSCRIPTEN_KEEPALIVE const char* FigureMeasured(int index) {
  const cgfs::Figure* figure = FigureAt(index);
  return Text(figure != nullptr && figure->measured ? figure->measured() : "");
}
EMSCRIPTEN_KEEPALIVE int FigureHasCamera(int index) {
  const cgfs::Figure* figure = FigureAt(index);
  return figure == nullptr ? -1 : figure->draw_from ? 1 : 0;
}

// The index of the figure the C key switches to from figure `index` (its cost view, or
// the figure whose cost view it is), or -1.
EMSCRIPTEN_KEEPALIVE int FigureCostPartner(int index) {
  const cgfs::Figure* figure = FigureAt(index);
  if (figure == nullptr) {
    return -1;
  }
  std::vector<const cgfs::Figure*> all;
  for (const cgfs::Figure& each : ChapterFigures()) {
    all.push_back(&each);
  }
  return cgfs::CostPartner(all, static_cast<std::size_t>(index));
}

// Whether figure `index` names a cost view of its own (1), or not (0; -1 out of range):
// the page's C button says where it goes.
EMSCRIPTEN_KEEPALIVE int FigureHasCostView(int index) {
  const cgfs::Figure* figure = FigureAt(index);
  return figure == nullptr ? -1 : figure->cost_view.empty() ? 0 : 1;
}

// Draws figure `index` at width x height, from the camera's view where the figure has a
// camera; the pixels, width x height x 4 bytes, then stand at Pixels(). 1, or 0 with
// LastError() saying why.
EMSCRIPTEN_KEEPALIVE int DrawFigure(int index, int width, int height) {
  const cgfs::Figure* figure = FigureAt(index);
  if (figure == nullptr) {
    return 0;
  }
  constexpr int kLargest = 4096;
  if (width < 2 || height < 2 || width > kLargest || height > kLargest || width % 2 != 0 ||
      height % 2 != 0) {
    last_error = "a figure is drawn at an even size from 2x2 to 4096x4096, not " +
                 std::to_string(width) + "x" + std::to_string(height);
    return 0;
  }
  try {
    const cgfs::Canvas canvas =
        cgfs::RenderFigure(*figure, width, height, figure->draw_from ? view : cgfs::View{});
    KeepAsRgba(canvas.GetImage().Bytes());
    return 1;
  } catch (const std::exception& error) {
    last_error = error.what();
    return 0;
  }
}
EMSCRIPTEN_KEEPALIVE const std::uint8_t* Pixels() {
  return pixels.data();
}
EMSCRIPTEN_KEEPALIVE const char* LastError() {
  return last_error.c_str();
}

// A reader's image of figure `index` (RGBA, width x height, from the page's "Your code"),
// compared with the figure drawn at that size from the chapter's own view, as cgfs-compare
// compares an image with a golden one: 1 when they match, 0 when not, -1 with LastError().
// ComparisonText() then says what cgfs-compare says (its numbers, verdict and diagnosis),
// Pixels() holds the difference image (its colours: DifferenceColours()), and
// DifferingColumn() and DifferingRow() the first differing pixel (-1 when none).
EMSCRIPTEN_KEEPALIVE int CompareWithFigure(int index, int width, int height,
                                           const std::uint8_t* rgba) {
  const cgfs::Figure* figure = FigureAt(index);
  if (figure == nullptr) {
    return -1;
  }
  try {
    const cgfs::Canvas ours = cgfs::RenderFigure(*figure, width, height, cgfs::View{});
    cgfs::Image theirs(width, height);
    for (int row = 0; row < height; ++row) {
      for (int column = 0; column < width; ++column) {
        const std::uint8_t* pixel = rgba + (static_cast<std::size_t>(row) * width + column) * 4;
        theirs.Set(column, row, {pixel[0], pixel[1], pixel[2]});
      }
    }
    comparison = cgfs::CompareImages(ours.GetImage(), theirs);
    KeepAsRgba(comparison.difference.Bytes());
    return comparison.passed ? 1 : 0;
  } catch (const std::exception& error) {
    last_error = error.what();
    return -1;
  }
}
EMSCRIPTEN_KEEPALIVE const char* ComparisonText() {
  return Text(
      cgfs::Describe(comparison, comparison.difference.Width(), comparison.difference.Height()));
}
// The difference image's colours, one to a line: "R,G,B NAME: MEANING".
EMSCRIPTEN_KEEPALIVE const char* DifferenceColours() {
  std::string lines;
  for (const cgfs::DifferenceColour& each : cgfs::kDifferenceColours) {
    lines += std::to_string(each.colour.r) + "," + std::to_string(each.colour.g) + "," +
             std::to_string(each.colour.b) + " " + each.name + ": " + each.meaning + "\n";
  }
  return Text(lines);
}
EMSCRIPTEN_KEEPALIVE int DifferingColumn() {
  return comparison.differing_pixels > 0 ? comparison.first_differing.column : -1;
}
EMSCRIPTEN_KEEPALIVE int DifferingRow() {
  return comparison.differing_pixels > 0 ? comparison.first_differing.row : -1;
}

// The camera: a key (a cgfs::CameraKey, 0 to 9), a drag, back to the chapter's view,
// or a view as --view takes it ("x,y,z,yaw,pitch": 1, or 0 with LastError()).
EMSCRIPTEN_KEEPALIVE void PressCameraKey(int key) {
  if (key >= 0 && key <= static_cast<int>(cgfs::CameraKey::kLookDown)) {
    view = cgfs::Moved(view, static_cast<cgfs::CameraKey>(key));
  }
}
EMSCRIPTEN_KEEPALIVE void DragCamera(int right, int down) {
  view = cgfs::Dragged(view, right, down);
}
EMSCRIPTEN_KEEPALIVE void ResetView() {
  view = cgfs::View{};
}
EMSCRIPTEN_KEEPALIVE int SetView(const char* value) {
  try {
    view = cgfs::ParseView(value);
    return 1;
  } catch (const std::exception& error) {
    last_error = error.what();
    return 0;
  }
}
EMSCRIPTEN_KEEPALIVE const char* ViewText() {
  return Text(cgfs::FormatView(view));
}
EMSCRIPTEN_KEEPALIVE int PreviewSide(int side) {
  return cgfs::PreviewSide(side);
}
EMSCRIPTEN_KEEPALIVE int SettleMilliseconds() {
  return cgfs::kSettleMilliseconds;
}

#if __has_include("options.h")
// The chapter's figures made anew with the options a command line would give, one word
// to a line ("--model\nspider.obj"; none: the chapter's own figures): files are read
// from the page's file system, where the page has put the reader's. 0 when the options
// were read, the figures made and the view reset; 2, with the line that says why on the
// standard error (where warnings go too, as from the program), when not: the figures
// stay as they were.
EMSCRIPTEN_KEEPALIVE int UseOptions(const char* lines) {
  std::vector<std::string> words;
  for (std::string_view rest = lines; !rest.empty();) {
    const std::size_t end = std::min(rest.find('\n'), rest.size());
    words.emplace_back(rest.substr(0, end));
    rest.remove_prefix(std::min(end + 1, rest.size()));
  }
  ChapterSettings settings;
  const int status = cgfs::ReadOptions(
      CGFS_CHAPTER, [&settings](CLI::App& app) { AddChapterOptions(app, settings); }, words);
  if (status == 0) {
    chapter_figures = Figures(settings);
    figures_made = true;
    view = cgfs::View{};
  }
  return status;
}
#endif

}  // extern "C"
