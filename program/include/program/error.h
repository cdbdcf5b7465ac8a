// Errors the user can fix, and the one place every program reports them.
#pragma once

#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace cgfs {

// A problem with the user's input (a file, a number, an option). Its message is
// one line, written so that it can be printed as it is.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A path as messages name it: in single quotes, 'like/this.png'.
std::string Quoted(const std::filesystem::path& path);

// The message with its control characters written as escapes (\n, \t, \x1b), so that it
// prints as one line whatever it echoes.
std::string OneLine(std::string_view message);

// A mistake on the command line; the report adds "(try --help)".
class UsageError : public Error {
 public:
  using Error::Error;
};

// Runs a program's body and turns whatever goes wrong into one line on standard
// error, "PROGRAM: error: ...", and exit status 2: our own errors, the command-line
// library's, the file system's, running out of memory, any other std::exception, and a
// standard output that cannot be written (a full disk, a closed pipe). Otherwise
// returns the body's status.
int RunReportingErrors(std::string_view program, const std::function<int()>& body);

// Something left out that the user should know of, while the program goes on (a model's
// material library that cannot be read): one line on standard error,
// "PROGRAM: warning: ...", PROGRAM as RunReportingErrors was given it.
void Warn(std::string_view message);

}  // namespace cgfs
