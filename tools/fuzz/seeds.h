// Small images of every kind ReadImage reads, for the fuzz target to start from:
// PNG (RGB, grey, grey and alpha, RGBA, 16-bit, interlaced is left to the fuzzer),
// JPEG (baseline and progressive are left to libjpeg's own variety: stb writes
// baseline), and PPM (P6 and P3).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace cgfs::fuzz {

// (file name, bytes) of each seed.
std::vector<std::pair<std::string, std::string>> MakeSeeds();

}  // namespace cgfs::fuzz
