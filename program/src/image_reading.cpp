// Reading images: ReadImage and DecodeImage (program/image_files.h), the PPM reader, and
// the declared-size check every decoder makes; PNG and JPEG are decoded by
// image_decoders.cpp (libpng, libjpeg-turbo), or on the web pages by the browser
// (program/web/image_decoders_web.cpp).
#include "program/image_files.h"

#include <cctype>
#include <cstdint>
#include <limits>
#include <string>

#include "image_decoders.h"
#include "program/error.h"
#include "program/file_reading.h"

namespace cgfs {

namespace fs = std::filesystem;

namespace detail {

void CheckDeclaredSize(long long width, long long height, const fs::path& path,
                       const std::string& kind) {
  if (width <= 0 || height <= 0 || width > kMaxSide || height > kMaxSide ||
      width * height > kMaxPixels) {
    throw Error(Quoted(path) + " is not a valid " + kind + " image: image size " +
                std::to_string(width) + "x" + std::to_string(height) +
                " is out of range (at most " + std::to_string(kMaxSide) + " a side and " +
                std::to_string(kMaxPixels) + " pixels)");
  }
}

}  // namespace detail

namespace {

// The largest file ReadImage reads: a plain-text P3 of 4096x4096 is about 200 MB.
constexpr std::uintmax_t kMaxFileBytes = 256u << 20;

// PPM, binary ("P6") or plain ("P3"): a header of whitespace-separated decimal
// numbers ('#' starts a comment), then the samples. stb's reader accepts a
// truncated P6 and fills the rest with zeros, so we read PPM ourselves.
class PpmReader {
 public:
  PpmReader(const std::string& bytes, const fs::path& path) : bytes_(bytes), path_(path) {}

  Image Read() {
    const bool binary = bytes_[1] == '6';
    pos_ = 2;  // past "P6" or "P3"
    const long width = Number("width");
    const long height = Number("height");
    const long maxval = Number("maximum value");
    detail::CheckDeclaredSize(width, height, path_, "PPM");
    if (maxval <= 0 || maxval > 65535) {
      Fail("maximum value " + std::to_string(maxval) + " is out of range 1..65535");
    }
    if (binary) {
      // Exactly one whitespace byte separates the header from the samples.
      if (pos_ >= bytes_.size() || !std::isspace(static_cast<unsigned char>(bytes_[pos_]))) {
        Fail("no whitespace after the header");
      }
      ++pos_;
      const std::size_t sample_bytes = maxval < 256 ? 1 : 2;
      const std::size_t needed =
          static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3 * sample_bytes;
      if (bytes_.size() - pos_ < needed) {
        Fail("the file ends after " + std::to_string(bytes_.size() - pos_) + " of " +
             std::to_string(needed) + " pixel bytes");
      }
    } else if (bytes_.size() - pos_ < static_cast<std::size_t>(width * height * 3 * 2 - 1)) {
      // Every sample is a digit and a separator: too few bytes, whatever they hold.
      Fail("the file is too short for " + std::to_string(width) + "x" + std::to_string(height) +
           " pixels");
    }

    Image image(static_cast<int>(width), static_cast<int>(height));
    for (int row = 0; row < image.Height(); ++row) {
      for (int column = 0; column < image.Width(); ++column) {
        std::uint8_t channel[3];
        for (std::uint8_t& c : channel) {
          const long sample = binary ? BinarySample(maxval) : Number("pixel value");
          if (sample > maxval) {
            Fail("pixel value " + std::to_string(sample) + " exceeds the maximum " +
                 std::to_string(maxval));
          }
          c = static_cast<std::uint8_t>((sample * 255 + maxval / 2) / maxval);
        }
        image.Set(column, row, {channel[0], channel[1], channel[2]});
      }
    }
    return image;
  }

 private:
  [[noreturn]] void Fail(const std::string& why) const {
    throw Error(Quoted(path_) + " is not a valid PPM image: " + why);
  }

  long BinarySample(long maxval) {
    const auto byte = [this] {
      return static_cast<long>(static_cast<unsigned char>(bytes_[pos_++]));
    };
    if (maxval < 256) {
      return byte();
    }
    const long high = byte();
    return high * 256 + byte();
  }

  long Number(const char* what) {
    for (;;) {
      while (pos_ < bytes_.size() && std::isspace(static_cast<unsigned char>(bytes_[pos_]))) {
        ++pos_;
      }
      if (pos_ < bytes_.size() && bytes_[pos_] == '#') {
        while (pos_ < bytes_.size() && bytes_[pos_] != '\n') {
          ++pos_;
        }
        continue;
      }
      break;
    }
    long value = 0;
    std::size_t digits = 0;
    while (pos_ < bytes_.size() && bytes_[pos_] >= '0' && bytes_[pos_] <= '9') {
      const int digit = bytes_[pos_] - '0';
      // Checked before it grows: no number here may pass INT_MAX, whatever long holds.
      if (value > (std::numeric_limits<int>::max() - digit) / 10) {
        Fail(std::string(what) + " is too large");
      }
      value = value * 10 + digit;
      ++pos_;
      ++digits;
    }
    if (digits == 0) {
      Fail(pos_ >= bytes_.size() ? std::string("the file ends before the ") + what
                                 : std::string("expected the ") + what);
    }
    return value;
  }

  const std::string& bytes_;
  const fs::path& path_;
  std::size_t pos_ = 0;
};

}  // namespace

Image DecodeImage(const std::string& bytes, const fs::path& path) {
  if (bytes.empty()) {
    throw Error(Quoted(path) + " is empty");
  }
  if (bytes.size() >= 2 && bytes[0] == 'P' && (bytes[1] == '3' || bytes[1] == '6')) {
    return PpmReader(bytes, path).Read();
  }
  if (bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0) {
    return detail::DecodePng(bytes, path);
  }
  if (bytes.compare(0, 3, "\xff\xd8\xff") == 0) {
    return detail::DecodeJpeg(bytes, path);
  }
  throw Error(Quoted(path) + " is neither a PNG, a JPEG nor a PPM (P3 or P6) image");
}

Image ReadImage(const fs::path& path) {
  return DecodeImage(ReadWholeFile(path, kMaxFileBytes), path);
}

}  // namespace cgfs
