// The PNG and JPEG decoders of the chapters' web pages, in place of image_decoders.cpp
// (the page's build has neither libpng nor libjpeg): the page decodes a PNG or JPEG file
// the reader chose with the browser's own decoder and gives the chapter's code its
// pixels as a binary PPM under the file's name (figures_worker.js), which
// image_reading.cpp reads as it reads any PPM. What reaches these is a file the browser
// could not decode.
#include <filesystem>
#include <string>

#include "../src/image_decoders.h"
#include "program/error.h"

namespace cgfs::detail {

Image DecodePng(const std::string&, const std::filesystem::path& path) {
  throw Error(Quoted(path) + " is not a PNG image this browser can decode");
}

Image DecodeJpeg(const std::string&, const std::filesystem::path& path) {
  throw Error(Quoted(path) + " is not a JPEG image this browser can decode");
}

}  // namespace cgfs::detail
