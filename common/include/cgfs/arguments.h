// Parsing a program's arguments with CLI11, the same way in every program.
#pragma once

namespace CLI {
class App;
}

namespace cgfs {

// Parses the arguments into the options declared on `app`. Prints the help and
// returns false for --help; throws (see RunReportingErrors) on anything wrong, with
// arguments that name no option reported in the order they were given.
bool ParseArguments(CLI::App& app, int argc, const char* const* argv);

}  // namespace cgfs
