// A fresh, empty folder per test case, removed when the test program ends.
#pragma once

#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include <unistd.h>

namespace cgfs::test {

// `prefix` names the folders in the system's temporary folder.
inline std::filesystem::path TemporaryFolder(const std::string& prefix) {
  struct MadeFolders {
    std::vector<std::filesystem::path> paths;
    ~MadeFolders() {
      for (const std::filesystem::path& path : paths) {
        std::error_code ignored;
        std::filesystem::remove_all(path, ignored);
      }
    }
  };
  static int counter = 0;
  static MadeFolders made;
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() /
      (prefix + "-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  made.paths.push_back(folder);
  return folder;
}

}  // namespace cgfs::test
