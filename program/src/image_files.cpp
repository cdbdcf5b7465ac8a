// Writing images: PNG with stb, PPM ourselves, through the one safe path (safe_file.h).
// Reading them is image_reading.cpp.
#include "program/image_files.h"

#include <stb_image_write.h>

#include <string>

#include "program/error.h"
#include "program/safe_file.h"

namespace cgfs {

namespace fs = std::filesystem;

namespace {

std::string ToLower(std::string text) {
  for (char& c : text) {
    if (c >= 'A' && c <= 'Z') {
      c = static_cast<char>(c - 'A' + 'a');
    }
  }
  return text;
}

void AppendToString(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                             static_cast<std::size_t>(size));
}

std::string EncodePng(const Image& image) {
  std::string encoded;
  if (stbi_write_png_to_func(AppendToString, &encoded, image.Width(), image.Height(), 3,
                             image.Bytes().data(), image.Width() * 3) == 0) {
    throw Error("cannot encode a " + std::to_string(image.Width()) + "x" +
                std::to_string(image.Height()) + " PNG");
  }
  return encoded;
}

std::string EncodePpm(const Image& image) {
  std::string encoded =
      "P6\n" + std::to_string(image.Width()) + " " + std::to_string(image.Height()) + "\n255\n";
  encoded.append(image.Bytes().begin(), image.Bytes().end());
  return encoded;
}

}  // namespace

std::string EncodeImage(const Image& image, const fs::path& name) {
  return ToLower(name.extension().string()) == ".ppm" ? EncodePpm(image) : EncodePng(image);
}

void WriteImage(const Image& image, const fs::path& path) {
  WriteFileSafely(path, EncodeImage(image, path));
}

}  // namespace cgfs
