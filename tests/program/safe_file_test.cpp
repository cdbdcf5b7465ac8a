// WriteFileSafely and CreateExclusively (program/safe_file.h): what stands at a path is
// never followed, opened or replaced unless it is a regular file, and a write leaves
// the whole new file or the old one, and no temporary.
#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "program/error.h"
#include "program/safe_file.h"

namespace fs = std::filesystem;

namespace {

fs::path ScratchFolder(const std::string& name) {
  const fs::path folder = fs::temp_directory_path() /
                          ("cgfs-safe-file-test-" + std::to_string(::getpid()) + "-" + name);
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

std::string Contents(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

int Temporaries(const fs::path& folder) {
  int count = 0;
  for (const auto& entry : fs::directory_iterator(folder)) {
    count += entry.path().filename().string().ends_with(".partial");
  }
  return count;
}

}  // namespace

TEST_CASE("WriteFileSafely writes a new file, then replaces it whole", "[safe-file]") {
  const fs::path folder = ScratchFolder("replace");
  cgfs::WriteFileSafely(folder / "a.txt", "first");
  CHECK(Contents(folder / "a.txt") == "first");
  cgfs::WriteFileSafely(folder / "a.txt", std::string(100000, 'x'));
  CHECK(Contents(folder / "a.txt") == std::string(100000, 'x'));
  CHECK(Temporaries(folder) == 0);
  fs::remove_all(folder);
}

TEST_CASE("WriteFileSafely refuses what is not a regular file and leaves it as it is",
          "[safe-file]") {
  const fs::path folder = ScratchFolder("refuse");
  REQUIRE(::mkfifo((folder / "fifo").c_str(), 0600) == 0);
  fs::create_directory(folder / "folder");
  std::ofstream(folder / "victim.txt") << "precious";
  fs::create_symlink(folder / "victim.txt", folder / "link");
  for (const char* name : {"fifo", "folder", "link"}) {
    INFO(name);
    CHECK_THROWS_WITH(cgfs::WriteFileSafely(folder / name, "data"),
                      Catch::Contains("not a regular file"));
  }
  CHECK(fs::is_fifo(folder / "fifo"));
  CHECK(fs::is_directory(folder / "folder"));
  CHECK(fs::is_symlink(folder / "link"));
  CHECK(Contents(folder / "victim.txt") == "precious");
  CHECK(Temporaries(folder) == 0);
  fs::remove_all(folder);
}

TEST_CASE("CreateExclusively neither follows a symbolic link nor opens a FIFO", "[safe-file]") {
  const fs::path folder = ScratchFolder("exclusive");
  std::ofstream(folder / "victim.txt") << "precious";
  fs::create_symlink(folder / "victim.txt", folder / "link");
  fs::create_symlink(folder / "nowhere", folder / "dangling");
  REQUIRE(::mkfifo((folder / "fifo").c_str(), 0600) == 0);
  for (const char* name : {"link", "dangling", "fifo"}) {
    INFO(name);
    errno = 0;
    CHECK(cgfs::CreateExclusively(folder / name) == -1);
    CHECK(errno == EEXIST);
  }
  CHECK(Contents(folder / "victim.txt") == "precious");
  CHECK_FALSE(fs::exists(folder / "nowhere"));
  const int fd = cgfs::CreateExclusively(folder / "new");
  CHECK(fd >= 0);
  ::close(fd);
  fs::remove_all(folder);
}

TEST_CASE("a write that fails says why and leaves no temporary", "[safe-file]") {
  const fs::path folder = ScratchFolder("fail");
  CHECK_THROWS_WITH(cgfs::WriteFileSafely(folder / "missing" / "a.txt", "data"),
                    Catch::Contains("No such file or directory"));
  if (fs::exists("/dev/full")) {
    // /dev/full as a folder cannot hold a file either; the disk-full case itself is
    // the command-line test's (standard output into /dev/full).
    CHECK_THROWS_AS(cgfs::WriteFileSafely("/dev/full/a.txt", "data"), cgfs::Error);
  }
  CHECK(Temporaries(folder) == 0);
  fs::remove_all(folder);
}
