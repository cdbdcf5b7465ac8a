// The program every chapter builds from its main.cpp: it draws the chapter's
// figures into out/<chapter>/, with the options every chapter shares (--output,
// --size, --figure, --format, --list, --window, --view, --help).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "program/figure.h"

namespace CLI {
class App;
}

namespace cgfs {

class ChapterProgram {
 public:
  ChapterProgram(std::string chapter, std::string description);
  ~ChapterProgram();

  // Where a chapter adds an option of its own, when the option is the chapter's
  // own idea (chapter 5's optimisations, for example), never to pick a scene.
  CLI::App& Options();

  // Parses the arguments, then asks `figures` for the chapter's figures (after parsing,
  // so that they are made with the settings the options gave), and draws and writes
  // the selected ones, printing each file and its render time. Returns the exit
  // status: 0, or 2 with a one-line error on bad input or a file that cannot be
  // written (nothing is written on bad input).
  int Run(int argc, const char* const* argv, const std::function<std::vector<Figure>()>& figures);

 private:
  int Parse(int argc, const char* const* argv);
  int DrawFigures(const std::vector<Figure>& figures) const;

  std::string chapter_;
  std::unique_ptr<CLI::App> options_;
  std::string output_;
  std::string size_ = "600x600";
  std::string format_ = "png";
  std::vector<std::string> selected_;
  bool list_ = false;
  bool window_ = false;
  std::string view_;
};

}  // namespace cgfs
