// Image files: PNG through stb, and the book-era PPM.
#pragma once

#include <filesystem>
#include <string>

#include "cgfs/image.h"

namespace cgfs {

// Writes PNG, or binary PPM (P6) when the file name ends in .ppm. The file is
// written next to its destination and renamed into place, so an existing file
// is replaced only by a complete new one. Throws cgfs::Error.
void WriteImage(const Image& image, const std::filesystem::path& path);

// The bytes of a PNG, or of a binary PPM (P6) when `name` ends in .ppm.
std::string EncodeImage(const Image& image, const std::filesystem::path& name);

// Reads PNG, JPEG, binary PPM (P6) or plain PPM (P3), whatever the file name says.
// Alpha is dropped and grey becomes RGB; PPM samples are scaled from their maximum
// value to 0..255. Throws cgfs::Error with a one-line reason.
Image ReadImage(const std::filesystem::path& path);

}  // namespace cgfs
