// The fuzz target of ReadImage's decoders (libpng, libjpeg-turbo, our PPM reader):
// any bytes must give an image within the size limits or one cgfs::Error, never a
// crash, a hang, a leak or an allocation past the limits. Built with libFuzzer by
// scripts/fuzz (clang, the `fuzz` preset), and replayed by fuzz-smoke in the tests.
#include <cstddef>
#include <cstdint>
#include <string>

#include "program/error.h"
#include "program/image_files.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const cgfs::Image image =
        cgfs::DecodeImage(std::string(reinterpret_cast<const char*>(data), size), "input");
    if (image.Width() <= 0 || image.Height() <= 0 ||
        static_cast<long long>(image.Width()) * image.Height() > 4096LL * 4096) {
      __builtin_trap();  // a size the limits should have refused
    }
  } catch (const cgfs::Error&) {
    // A one-line refusal is the right answer to bad bytes.
  }
  return 0;
}
