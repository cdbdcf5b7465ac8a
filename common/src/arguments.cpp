#include "cgfs/arguments.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <string>

#include "cgfs/error.h"

namespace cgfs {

bool ParseArguments(CLI::App& app, int argc, const char* const* argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    return false;
  } catch (const CLI::ExtrasError&) {
    std::string extras;
    for (const std::string& argument : app.remaining()) {
      extras += (extras.empty() ? "" : " ") + argument;
    }
    throw UsageError("unexpected arguments: " + extras);
  }
  return true;
}

}  // namespace cgfs
