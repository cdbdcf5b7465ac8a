#include "cgfs/arguments.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <string>
#include <utility>

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

void AddTextOption(CLI::App& app, const std::string& name, std::string& value,
                   const std::string& help, const std::string& type_name) {
  app.add_option("--" + name, value, help)->type_name(type_name);
}

void AddIntOption(CLI::App& app, const std::string& name, int& value, const std::string& help,
                  const std::string& type_name, int min, int max) {
  app.add_option("--" + name, value, help)->type_name(type_name)->check(CLI::Range(min, max));
}

void SetDefaultSize(CLI::App& app, const std::string& size) {
  CLI::Option* option = app.get_option("--size");
  const std::string help = option->get_description();
  const std::size_t start = help.find("(default ");
  option->default_val(size)->description(help.substr(0, start) + "(default " + size + ")");
}

void AfterParsing(CLI::App& app, std::function<void()> callback) {
  app.final_callback(std::move(callback));
}

}  // namespace cgfs
