// Parsing a program's arguments with CLI11, the same way in every program.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace cgfs {

// Parses the arguments into the options declared on `app`. Prints the help and
// returns false for --help; throws (see RunReportingErrors) on anything wrong, with
// arguments that name no option reported in the order they were given.
bool ParseArguments(CLI::App& app, int argc, const char* const* argv);

// For a chapter's options.cpp, without including CLI11 (a large header that takes
// seconds to compile): an option `--name VALUE` read into `value`, shown in the help
// as `--name TYPE_NAME  help`; an empty VALUE is refused (every such option names a file).
void AddTextOption(CLI::App& app, const std::string& name, std::string& value,
                   const std::string& help, const std::string& type_name);

// The same for a whole number: `--name N`, accepted only in [min, max].
void AddIntOption(CLI::App& app, const std::string& name, int& value, const std::string& help,
                  const std::string& type_name, int min, int max);

// The same for a comma list of names, each one of `allowed`: `--name a,b,c`, in the
// order given. CLI11 splits the list and reports a name it does not know, or an empty
// list, as any other error.
void AddListOption(CLI::App& app, const std::string& name, std::vector<std::string>& values,
                   const std::string& help, const std::string& type_name,
                   const std::vector<std::string>& allowed);

// --model FILE.obj: a Wavefront OBJ model of the reader's own (read with
// ReadBookModel, program/book_model.h), drawn as `figures` instead of the chapter's own.
void AddModelOption(CLI::App& app, std::string& file, const std::string& figures);

// --threads N, the workers when 'threads' is among the chosen optimisations (0: not
// given); and the workers a chapter uses: `chosen` as its optimisations give it (1
// without 'threads', one per core with it), or N where given. A UsageError for N > 1
// without 'threads'.
void AddThreadsOption(CLI::App& app, int& threads);
int WorkersChosen(int chosen, int threads);

// For a chapter whose figures have a size of their own (the business card is
// 512x512): the --size the chapter program uses when none is given.
void SetDefaultSize(CLI::App& app, const std::string& size);

// Runs `callback` once the whole command line has been read, before anything is
// drawn; what it throws is reported like any other error (RunReportingErrors). One per
// program (CLI11 keeps one: a second replaces the first).
void AfterParsing(CLI::App& app, std::function<void()> callback);

}  // namespace cgfs
