#include "program/error.h"

#include <CLI/Error.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <new>
#include <string>

namespace cgfs {

std::string Quoted(const std::filesystem::path& path) {
  std::string quoted(1, '\'');  // not "'" + string: that trips GCC 12's -Wrestrict (bug 105329)
  quoted += path.string();
  quoted += '\'';
  return quoted;
}

// Control characters written as escapes, \n, \t, \x1b, so that a message that echoes a
// value given with a newline in it, or a file name with a tab, stays one line.
std::string OneLine(std::string_view message) {
  std::string line;
  for (const char c : message) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\n') {
      line += "\\n";
    } else if (c == '\r') {
      line += "\\r";
    } else if (c == '\t') {
      line += "\\t";
    } else if (byte < 0x20 || byte == 0x7f) {
      char escape[5];
      std::snprintf(escape, sizeof escape, "\\x%02x", byte);
      line += escape;
    } else {
      line += c;
    }
  }
  return line;
}

namespace {

// Everything a program printed must have reached its destination: `--list > /dev/full`
// is an error, not a silent success.
void FlushStandardOutput() {
  std::cout.flush();
  if (!std::cout || std::fflush(stdout) != 0 || std::ferror(stdout)) {
    throw Error("cannot write to standard output");
  }
}

// The program's name, for warnings (RunReportingErrors sets it).
std::string program_name = "cgfs";

int Report(std::string_view program, const std::string& message, bool usage) {
  std::cerr << program << ": error: " << OneLine(message) << (usage ? " (try --help)" : "") << "\n";
  return 2;
}

}  // namespace

int RunReportingErrors(std::string_view program, const std::function<int()>& body) {
  program_name = program;
  try {
    const int status = body();
    FlushStandardOutput();
    return status;
  } catch (const UsageError& error) {
    return Report(program, error.what(), true);
  } catch (const Error& error) {
    return Report(program, error.what(), false);
  } catch (const CLI::ParseError& error) {
    return Report(program, error.what(), true);
  } catch (const std::filesystem::filesystem_error& error) {
    // Its message names the operation and the path: "filesystem error: ... [path]".
    return Report(program, error.what(), false);
  } catch (const std::bad_alloc&) {
    return Report(program, "out of memory", false);
  } catch (const std::exception& error) {
    // Anything else the standard library throws (a thread that cannot be started, a
    // string too long...): still one line, never std::terminate.
    return Report(program, error.what(), false);
  }
}

void Warn(std::string_view message) {
  std::cerr << program_name << ": warning: " << OneLine(message) << "\n";
}

}  // namespace cgfs
