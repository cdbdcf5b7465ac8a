// Image files: PNG (written with stb, read with libpng), JPEG (read with libjpeg-turbo)
// and the book-era PPM.
#pragma once

#include <filesystem>
#include <string>

#include "cgfs/image.h"

namespace cgfs {

// Writes PNG, or binary PPM (P6) when the file name ends in .ppm, through
// WriteFileSafely (safe_file.h): an existing file is replaced only by a complete new
// one, and a destination that is not a regular file is refused. Throws cgfs::Error.
void WriteImage(const Image& image, const std::filesystem::path& path);

// The bytes of a PNG, or of a binary PPM (P6) when `name` ends in .ppm.
std::string EncodeImage(const Image& image, const std::filesystem::path& name);

// Reads PNG (libpng), JPEG (libjpeg-turbo), binary PPM (P6) or plain PPM (P3),
// whatever the file name says. Alpha is dropped and grey becomes RGB; 16-bit samples
// are cut to 8; PPM samples are scaled from their maximum value to 0..255. A size
// beyond 16384 a side or 4096x4096 pixels is refused from the header, before any pixel
// is allocated. Throws cgfs::Error with a one-line reason.
Image ReadImage(const std::filesystem::path& path);

// The same for bytes already read; `path` only names them in messages.
Image DecodeImage(const std::string& bytes, const std::filesystem::path& path);

}  // namespace cgfs
