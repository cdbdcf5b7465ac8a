#include "program/arguments.h"

#include <CLI/CLI.hpp>

#include <charconv>
#include <iostream>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "program/error.h"

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
  app.add_option("--" + name, value, help)
      ->type_name(type_name)
      ->check([](const std::string& text) -> std::string {
        return text.empty() ? "an empty name: give a file" : "";
      });
}

void AddListOption(CLI::App& app, const std::string& name, std::vector<std::string>& values,
                   const std::string& help, const std::string& type_name,
                   const std::vector<std::string>& allowed) {
  app.add_option("--" + name, values, help)
      ->type_name(type_name)
      ->delimiter(',')
      ->check(CLI::IsMember(allowed));
}

void AddIntOption(CLI::App& app, const std::string& name, int& value, const std::string& help,
                  const std::string& type_name, int min, int max) {
  app.add_option("--" + name, value, help)
      ->type_name(type_name)
      ->check([min, max](const std::string& text) -> std::string {
        long long number = 0;
        const char* last = text.data() + text.size();
        const auto [stop, error] = std::from_chars(text.data(), last, number);
        if (text.empty() || error == std::errc::invalid_argument || stop != last) {
          return "'" + text + "' is not a whole number";
        }
        if (error == std::errc::result_out_of_range || number < min || number > max) {
          return "must be " + std::to_string(min) + ".." + std::to_string(max) + ", not " + text;
        }
        return "";
      });
}

void AddModelOption(CLI::App& app, std::string& file, const std::string& figures) {
  AddTextOption(app, "model", file,
                "a Wavefront OBJ model to draw instead of the chapter's figures (" + figures +
                    ", in front of the camera)",
                "FILE.obj");
}

namespace {

constexpr int kMaxThreads = 256;

}  // namespace

void AddThreadsOption(CLI::App& app, int& threads) {
  AddIntOption(app, "threads", threads, "workers when 'threads' is on (default: one per core)", "N",
               1, kMaxThreads);
}

int WorkersChosen(int chosen, int threads) {
  if (threads > 1 && chosen == 1) {
    throw UsageError("--threads " + std::to_string(threads) +
                     " needs 'threads' in --optimizations");
  }
  return threads > 0 && chosen > 1 ? threads : chosen;
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
