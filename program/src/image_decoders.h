// The decoders ReadImage trusts with files from anywhere: libpng for PNG and
// libjpeg-turbo for JPEG, both hardened by years of continuous fuzzing, and our own
// reader for PPM (image_reading.cpp). Private to program/; the web pages' build has
// image_decoders_web.cpp in its place.
#pragma once

#include <filesystem>
#include <string>

#include "cgfs/image.h"

namespace cgfs::detail {

// What ReadImage accepts, checked from the header before anything of that size is
// allocated: the chapters draw at most 4096x4096.
inline constexpr long long kMaxSide = 1 << 14;
inline constexpr long long kMaxPixels = 4096LL * 4096;

// Throws cgfs::Error unless a declared image size is one ReadImage accepts.
void CheckDeclaredSize(long long width, long long height, const std::filesystem::path& path,
                       const std::string& kind);

// The file's bytes as an RGB image: alpha dropped, grey made RGB, 16-bit samples cut to
// 8, palettes expanded. Throws cgfs::Error with a one-line reason.
Image DecodePng(const std::string& bytes, const std::filesystem::path& path);
Image DecodeJpeg(const std::string& bytes, const std::filesystem::path& path);

}  // namespace cgfs::detail
