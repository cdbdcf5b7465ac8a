#include "cgfs/command_line.h"

#include <charconv>
#include <iostream>
#include <sstream>

namespace cgfs {

int ParseInt(std::string_view text, std::string_view what, int min, int max) {
  int value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error == std::errc::invalid_argument || stop != end) {
    throw UsageError(std::string(what) + ": '" + std::string(text) + "' is not a whole number");
  }
  if (error == std::errc::result_out_of_range || value < min || value > max) {
    throw UsageError(std::string(what) + ": " + std::string(text) + " is out of range " +
                     std::to_string(min) + ".." + std::to_string(max));
  }
  return value;
}

void ParseSize(std::string_view text, std::string_view what, int min, int max, int* width,
               int* height) {
  const std::size_t x = text.find('x');
  if (x == std::string_view::npos) {
    throw UsageError(std::string(what) + ": '" + std::string(text) +
                     "' is not a size like 600x600");
  }
  const int w = ParseInt(text.substr(0, x), std::string(what) + " width", min, max);
  const int h = ParseInt(text.substr(x + 1), std::string(what) + " height", min, max);
  if (w % 2 != 0 || h % 2 != 0) {
    throw UsageError(
        std::string(what) + ": " + std::string(text) +
        " has an odd side; the canvas centre must fall between pixels, use even sizes");
  }
  *width = w;
  *height = h;
}

CommandLine::CommandLine(std::string program, std::string description)
    : program_(std::move(program)), description_(std::move(description)) {}

void CommandLine::AddFlag(std::string name, std::string help, bool* value) {
  options_.push_back(
      {std::move(name), "", std::move(help), [value](std::string_view) { *value = true; }});
}

void CommandLine::AddInt(std::string name, std::string value_name, std::string help, int* value,
                         int min, int max) {
  std::string what = name;
  options_.push_back({std::move(name), std::move(value_name), std::move(help),
                      [value, what, min, max](std::string_view text) {
                        *value = ParseInt(text, what, min, max);
                      }});
}

void CommandLine::AddString(std::string name, std::string value_name, std::string help,
                            std::string* value) {
  options_.push_back({std::move(name), std::move(value_name), std::move(help),
                      [value](std::string_view text) { *value = std::string(text); }});
}

void CommandLine::AddStrings(std::string name, std::string value_name, std::string help,
                             std::vector<std::string>* values) {
  options_.push_back({std::move(name), std::move(value_name), std::move(help),
                      [values](std::string_view text) { values->emplace_back(text); }});
}

void CommandLine::SetPositionals(std::vector<std::string> names, std::vector<std::string>* values) {
  positional_names_ = std::move(names);
  positionals_ = values;
}

const CommandLine::Option* CommandLine::Find(std::string_view name) const {
  for (const Option& option : options_) {
    if (option.name == name) {
      return &option;
    }
  }
  return nullptr;
}

bool CommandLine::Parse(int argc, const char* const* argv) {
  std::vector<std::string> positionals;
  for (int i = 1; i < argc; ++i) {
    const std::string_view argument = argv[i];
    if (argument == "--help" || argument == "-h") {
      std::cout << Help();
      return false;
    }
    if (argument.size() < 2 || argument.substr(0, 2) != "--") {
      if (!argument.empty() && argument[0] == '-' && argument != "-") {
        throw UsageError("unknown option '" + std::string(argument) + "'");
      }
      positionals.emplace_back(argument);
      continue;
    }
    const std::size_t equals = argument.find('=');
    const std::string_view name = argument.substr(0, equals);
    const Option* option = Find(name);
    if (option == nullptr) {
      throw UsageError("unknown option '" + std::string(name) + "'");
    }
    if (option->value_name.empty()) {
      if (equals != std::string_view::npos) {
        throw UsageError(std::string(name) + " takes no value");
      }
      option->set({});
      continue;
    }
    if (equals != std::string_view::npos) {
      option->set(argument.substr(equals + 1));
    } else if (i + 1 < argc) {
      option->set(argv[++i]);
    } else {
      throw UsageError(std::string(name) + " needs a value (" + option->value_name + ")");
    }
  }
  if (positionals_ == nullptr && !positionals.empty()) {
    throw UsageError("unexpected argument '" + positionals.front() + "'");
  }
  if (positionals_ != nullptr) {
    if (positionals.size() != positional_names_.size()) {
      throw UsageError("expected " + std::to_string(positional_names_.size()) + " arguments, got " +
                       std::to_string(positionals.size()));
    }
    *positionals_ = std::move(positionals);
  }
  return true;
}

std::string CommandLine::Help() const {
  std::ostringstream out;
  out << "usage: " << program_ << " [options]";
  for (const std::string& name : positional_names_) {
    out << " " << name;
  }
  out << "\n\n" << description_ << "\n\noptions:\n";
  for (const Option& option : options_) {
    std::string left = "  " + option.name;
    if (!option.value_name.empty()) {
      left += " " + option.value_name;
    }
    out << left << std::string(left.size() < 28 ? 28 - left.size() : 1, ' ') << option.help << "\n";
  }
  out << "  --help" << std::string(20, ' ') << "show this help and exit\n";
  return out.str();
}

}  // namespace cgfs
