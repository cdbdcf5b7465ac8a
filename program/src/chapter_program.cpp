#include "program/chapter_program.h"

#include <CLI/CLI.hpp>

#include <charconv>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <system_error>

#include <unistd.h>

#include "program/arguments.h"
#include "program/error.h"
#include "program/image_files.h"
#include "program/progress_display.h"
#include "program/window.h"

namespace cgfs {

namespace fs = std::filesystem;

namespace {

constexpr int kMinSide = 2;
constexpr int kMaxSide = 4096;

struct Size {
  int width = 0;
  int height = 0;
};

// "WIDTHxHEIGHT", each side an even whole number in [kMinSide, kMaxSide]. Returns
// the reason it is not, or an empty string.
std::string CheckSize(const std::string& text, Size* size = nullptr) {
  const std::size_t x = text.find('x');
  if (x == std::string::npos) {
    return "'" + text + "' is not a size like 600x600";
  }
  int sides[2] = {0, 0};
  const std::string parts[2] = {text.substr(0, x), text.substr(x + 1)};
  for (int i = 0; i < 2; ++i) {
    const char* first = parts[i].data();
    const char* last = first + parts[i].size();
    const auto [stop, error] = std::from_chars(first, last, sides[i]);
    if (parts[i].empty() || error == std::errc::invalid_argument || stop != last) {
      return "'" + text + "' is not a size like 600x600";
    }
    if (error == std::errc::result_out_of_range || sides[i] < kMinSide || sides[i] > kMaxSide) {
      return "sides must be " + std::to_string(kMinSide) + ".." + std::to_string(kMaxSide) +
             ", not " + parts[i];
    }
  }
  if (sides[0] % 2 != 0 || sides[1] % 2 != 0) {
    return text + " has an odd side; the canvas centre must fall between pixels, use even sizes";
  }
  if (size != nullptr) {
    *size = {sides[0], sides[1]};
  }
  return "";
}

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

ChapterProgram::ChapterProgram(std::string chapter, std::string description)
    : chapter_(std::move(chapter)),
      options_(std::make_unique<CLI::App>(std::move(description), chapter_)),
      output_("out/" + chapter_) {
  CLI::App& app = *options_;
  app.add_option("--output", output_, "folder for the images (default out/" + chapter_ + ")")
      ->type_name("DIR");
  app.add_option("--size", size_, "canvas size, even numbers 2..4096 (default 600x600)")
      ->type_name("WxH")
      ->check([](const std::string& text) { return CheckSize(text); });
  app.add_option("--figure", selected_, "draw only this figure (repeatable; see --list)")
      ->type_name("NAME")
      ->allow_extra_args(false);
  app.add_option("--format", format_, "image file format (default png)")
      ->type_name("FORMAT")
      ->check(CLI::IsMember({"png", "ppm"}));
  app.add_flag("--list", list_, "list the figures and exit")->disable_flag_override();
  app.add_flag("--window", window_,
               "show the figures in a window instead of writing them (Left/Right, S saves)")
      ->disable_flag_override();
  app.add_option("--view", view_,
                 "draw from a moved camera, as --window's S prints it (figures with a camera)")
      ->type_name("X,Y,Z,YAW,PITCH")
      ->check([](const std::string& text) {
        try {
          ParseView(text);
          return std::string();
        } catch (const Error& error) {
          return std::string(error.what());
        }
      });
}

ChapterProgram::~ChapterProgram() = default;

CLI::App& ChapterProgram::Options() {
  return *options_;
}

int ChapterProgram::Run(int argc, const char* const* argv,
                        const std::function<std::vector<Figure>()>& figures) {
  return RunReportingErrors(chapter_, [&] {
    if (!ParseArguments(*options_, argc, argv)) {
      return 0;
    }
    return DrawFigures(figures());
  });
}

int ChapterProgram::DrawFigures(const std::vector<Figure>& figures) const {
  Size size;
  CheckSize(size_, &size);
  const std::vector<const Figure*> selected = SelectFigures(figures, selected_);
  if (list_) {
    for (const Figure* figure : selected) {
      std::cout << figure->name << "  " << figure->caption << "\n";
    }
    return 0;
  }

  const View view = view_.empty() ? View{} : ParseView(view_);
  for (const Figure* figure : selected) {
    if (!(view == View{}) && !figure->draw_from) {
      throw UsageError("--view: figure '" + figure->name + "' has no camera to move");
    }
  }
  if (window_) {
    ShowFigures(chapter_, selected, size.width, size.height, output_, format_, view);
    return 0;
  }
  CreateOutputFolder(output_);
  for (const Figure* figure : selected) {
    const auto start = std::chrono::steady_clock::now();
    std::optional<ProgressDisplay> progress;
    progress.emplace(figure->name, isatty(STDERR_FILENO) == 1);
    const Canvas canvas = RenderFigure(*figure, size.width, size.height, view);
    progress.reset();
    const std::chrono::duration<double, std::milli> elapsed =
        std::chrono::steady_clock::now() - start;
    const fs::path file = fs::path(output_) / (figure->name + "." + format_);
    WriteImage(canvas.GetImage(), file);
    char time[32];
    std::snprintf(time, sizeof time, "%.1f", elapsed.count());
    std::cout << "wrote " << file.string() << "  (" << size.width << "x" << size.height
              << ", rendered in " << time << " ms)  " << CaptionOfDrawn(*figure) << "\n";
  }
  return 0;
}

}  // namespace cgfs
