// A small command-line parser shared by the chapter programs and the tools.
// Options look like --name VALUE or --name=VALUE; anything wrong is reported
// by a UsageError whose message is one line.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "cgfs/error.h"

namespace cgfs {

class UsageError : public Error {
 public:
  using Error::Error;
};

// Whole-string decimal integer in [min, max]; `what` names it in the error.
int ParseInt(std::string_view text, std::string_view what, int min, int max);

// "WIDTHxHEIGHT", each an even number in [min, max].
void ParseSize(std::string_view text, std::string_view what, int min, int max, int* width,
               int* height);

class CommandLine {
 public:
  CommandLine(std::string program, std::string description);

  void AddFlag(std::string name, std::string help, bool* value);
  void AddInt(std::string name, std::string value_name, std::string help, int* value, int min,
              int max);
  void AddString(std::string name, std::string value_name, std::string help, std::string* value);
  // May be given several times; each value is appended.
  void AddStrings(std::string name, std::string value_name, std::string help,
                  std::vector<std::string>* values);
  // The remaining non-option arguments, in order; exactly `count` are required.
  void SetPositionals(std::vector<std::string> names, std::vector<std::string>* values);

  // Returns false after printing the help for --help. Throws UsageError.
  bool Parse(int argc, const char* const* argv);
  std::string Help() const;

 private:
  struct Option {
    std::string name;
    std::string value_name;  // empty for flags
    std::string help;
    std::function<void(std::string_view)> set;
  };
  const Option* Find(std::string_view name) const;

  std::string program_;
  std::string description_;
  std::vector<Option> options_;
  std::vector<std::string> positional_names_;
  std::vector<std::string>* positionals_ = nullptr;
};

}  // namespace cgfs
