// fuzz-seeds FOLDER: writes the fuzz target's seeds (seeds.h) into FOLDER.
#include <filesystem>
#include <iostream>

#include "program/error.h"
#include "program/safe_file.h"
#include "seeds.h"

int main(int argc, char** argv) {
  return cgfs::RunReportingErrors("fuzz-seeds", [&] {
    if (argc != 2) {
      throw cgfs::UsageError("usage: fuzz-seeds FOLDER");
    }
    const std::filesystem::path folder = argv[1];
    std::filesystem::create_directories(folder);
    for (const auto& [name, bytes] : cgfs::fuzz::MakeSeeds()) {
      cgfs::WriteFileSafely(folder / name, bytes);
    }
    std::cout << "wrote " << cgfs::fuzz::MakeSeeds().size() << " seeds into " << folder.string()
              << "\n";
    return 0;
  });
}
