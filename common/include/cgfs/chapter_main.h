// The command line every chapter program shares: which figures, what size,
// where to write them. A chapter may add options of its own before Run().
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "cgfs/command_line.h"
#include "cgfs/figure.h"

namespace cgfs {

class ChapterProgram {
 public:
  ChapterProgram(std::string chapter, std::string description);

  CommandLine& Options() { return command_line_; }

  // Parses the arguments, then draws and writes the selected figures, printing
  // each file and its render time. `figures` is called after parsing, so it can
  // use the chapter's own options. Returns the exit status: 0, or 2 with a
  // one-line error on bad input or a file that cannot be written.
  int Run(int argc, const char* const* argv, const std::function<std::vector<Figure>()>& figures);

 private:
  std::string chapter_;
  CommandLine command_line_;
  std::string output_;
  std::string size_ = "600x600";
  std::string format_ = "png";
  std::vector<std::string> selected_;
  bool list_ = false;
};

}  // namespace cgfs
