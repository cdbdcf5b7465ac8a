#include "program/file_reading.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <system_error>

#include "program/error.h"

namespace cgfs {

namespace fs = std::filesystem;

std::string ReadWholeFile(const fs::path& path, std::uintmax_t max_bytes) {
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (error) {
    throw Error("cannot read " + Quoted(path) + ": " + error.message());
  }
  if (status.type() == fs::file_type::directory) {
    throw Error("cannot read " + Quoted(path) + ": it is a directory");
  }
  if (status.type() != fs::file_type::regular) {
    throw Error("cannot read " + Quoted(path) + ": not a regular file");
  }
  const auto too_large = [&] {
    return Error(Quoted(path) + " is too large: more than " + std::to_string(max_bytes) + " bytes");
  };
  if (const std::uintmax_t stated = fs::file_size(path, error); !error && stated > max_bytes) {
    throw too_large();
  }
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), std::fclose);
  if (!file) {
    throw Error("cannot read " + Quoted(path) + ": " + std::strerror(errno));
  }
  std::string bytes;
  char chunk[1 << 16];
  for (;;) {
    const std::size_t got = std::fread(chunk, 1, sizeof chunk, file.get());
    bytes.append(chunk, got);
    if (bytes.size() > max_bytes) {
      throw too_large();
    }
    if (got < sizeof chunk) {
      break;
    }
  }
  if (std::ferror(file.get())) {
    throw Error("cannot read " + Quoted(path) + ": " + std::strerror(errno));
  }
  return bytes;
}

}  // namespace cgfs
