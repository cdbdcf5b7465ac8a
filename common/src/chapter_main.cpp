#include "cgfs/chapter_main.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <system_error>

#include "cgfs/image_io.h"

namespace cgfs {

namespace fs = std::filesystem;

namespace {

constexpr int kMinSide = 2;
constexpr int kMaxSide = 4096;

std::vector<const Figure*> SelectFigures(const std::vector<Figure>& figures,
                                         const std::vector<std::string>& names) {
  std::vector<const Figure*> selected;
  if (names.empty()) {
    for (const Figure& figure : figures) {
      selected.push_back(&figure);
    }
    return selected;
  }
  for (const std::string& name : names) {
    const Figure* found = nullptr;
    for (const Figure& figure : figures) {
      if (figure.name == name) {
        found = &figure;
      }
    }
    if (found == nullptr) {
      std::string known;
      for (const Figure& figure : figures) {
        known += (known.empty() ? "" : ", ") + figure.name;
      }
      throw UsageError("--figure: no figure named '" + name + "'; this chapter has " + known);
    }
    selected.push_back(found);
  }
  return selected;
}

void CreateOutputFolder(const fs::path& folder) {
  std::error_code error;
  fs::create_directories(folder, error);
  if (error || !fs::is_directory(folder)) {
    throw Error("cannot create the output folder '" + folder.string() +
                "': " + (error ? error.message() : "a file of that name is in the way"));
  }
}

}  // namespace

Canvas RenderFigure(const Figure& figure, int width, int height) {
  Canvas canvas(width, height);
  figure.draw(canvas);
  return canvas;
}

ChapterProgram::ChapterProgram(std::string chapter, std::string description)
    : chapter_(chapter), command_line_(chapter, std::move(description)), output_("out/" + chapter) {
  command_line_.AddString("--output", "DIR", "folder for the images (default out/" + chapter + ")",
                          &output_);
  command_line_.AddString("--size", "WxH", "canvas size, even numbers 2..4096 (default 600x600)",
                          &size_);
  command_line_.AddStrings("--figure", "NAME", "draw only this figure (repeatable; see --list)",
                           &selected_);
  command_line_.AddString("--format", "png|ppm", "image file format (default png)", &format_);
  command_line_.AddFlag("--list", "list the figures and exit", &list_);
}

int ChapterProgram::Run(int argc, const char* const* argv,
                        const std::function<std::vector<Figure>()>& figures) {
  try {
    if (!command_line_.Parse(argc, argv)) {
      return 0;
    }
    int width = 0;
    int height = 0;
    ParseSize(size_, "--size", kMinSide, kMaxSide, &width, &height);
    if (format_ != "png" && format_ != "ppm") {
      throw UsageError("--format: '" + format_ + "' is not png or ppm");
    }
    const std::vector<Figure> all = figures();
    const std::vector<const Figure*> selected = SelectFigures(all, selected_);
    if (list_) {
      for (const Figure* figure : selected) {
        std::cout << figure->name << "  " << figure->caption << "\n";
      }
      return 0;
    }

    CreateOutputFolder(output_);
    for (const Figure* figure : selected) {
      const auto start = std::chrono::steady_clock::now();
      const Canvas canvas = RenderFigure(*figure, width, height);
      const std::chrono::duration<double, std::milli> elapsed =
          std::chrono::steady_clock::now() - start;
      const fs::path file = fs::path(output_) / (figure->name + "." + format_);
      WriteImage(canvas.GetImage(), file);
      std::printf("wrote %s  (%dx%d, rendered in %.1f ms)  %s\n", file.string().c_str(), width,
                  height, elapsed.count(), figure->caption.c_str());
    }
    return 0;
  } catch (const UsageError& error) {
    std::cerr << chapter_ << ": error: " << error.what() << " (try --help)\n";
    return 2;
  } catch (const Error& error) {
    std::cerr << chapter_ << ": error: " << error.what() << "\n";
    return 2;
  }
}

}  // namespace cgfs
