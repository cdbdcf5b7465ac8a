#include "web_options.h"

#include <CLI/CLI.hpp>

#include "program/arguments.h"
#include "program/error.h"

namespace cgfs {

int ReadOptions(const char* program, const std::function<void(CLI::App&)>& declare,
                const std::vector<std::string>& words) {
  return RunReportingErrors(program, [&] {
    CLI::App app;
    declare(app);
    std::vector<const char*> argv{program};
    for (const std::string& word : words) {
      argv.push_back(word.c_str());
    }
    ParseArguments(app, static_cast<int>(argv.size()), argv.data());
    return 0;
  });
}

}  // namespace cgfs
