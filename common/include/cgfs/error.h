#pragma once

#include <stdexcept>

namespace cgfs {

// A problem with the user's input (a file, a number, an option). Its message is
// one line, written so that main() can print it as it is.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace cgfs
