#include "cgfs/image_io.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <system_error>

#include "cgfs/error.h"

namespace cgfs {

namespace fs = std::filesystem;

namespace {

// What ReadImage accepts, checked before anything of that size is allocated: the
// chapters draw at most 4096x4096, and a plain-text P3 of that size is ~200 MB.
constexpr long kMaxSide = 1 << 14;
constexpr long long kMaxPixels = 4096LL * 4096;
constexpr std::uintmax_t kMaxFileBytes = 256u << 20;

std::string Quoted(const fs::path& path) {
  std::string quoted(1, '\'');  // not "'" + string: that trips GCC 12's -Wrestrict (bug 105329)
  quoted += path.string();
  quoted += '\'';
  return quoted;
}

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

// A regular file (after symbolic links) of at most kMaxFileBytes: never a FIFO that
// blocks, a device without end such as /dev/zero, a folder or a symbolic-link loop.
std::string ReadWholeFile(const fs::path& path) {
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (error) {
    throw Error("cannot read " + Quoted(path) + ": " + error.message());
  }
  if (status.type() == fs::file_type::directory) {
    throw Error("cannot read " + Quoted(path) + ": it is a directory");
  }
  if (status.type() != fs::file_type::regular) {
    throw Error("cannot read " + Quoted(path) + ": not a regular file");
  }
  const std::uintmax_t size = fs::file_size(path, error);
  if (error) {
    throw Error("cannot read " + Quoted(path) + ": " + error.message());
  }
  if (size > kMaxFileBytes) {
    throw Error(Quoted(path) + " is too large: " + std::to_string(size) + " bytes, at most " +
                std::to_string(kMaxFileBytes) + " are read");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw Error("cannot read " + Quoted(path) + ": " + std::strerror(errno));
  }
  // Read no more than was announced, even if the file grows meanwhile.
  std::string bytes(static_cast<std::size_t>(size), '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(size));
  if (in.bad()) {
    throw Error("cannot read " + Quoted(path));
  }
  bytes.resize(static_cast<std::size_t>(in.gcount()));
  return bytes;
}

// Throws unless a declared image size is one ReadImage accepts.
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
    CheckDeclaredSize(width, height, path_, "PPM");
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
      value = value * 10 + (bytes_[pos_] - '0');
      if (value > std::numeric_limits<int>::max()) {
        Fail(std::string(what) + " is too large");
      }
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

// PNG or JPEG, which stb_image tells apart by their first bytes; `format` names it
// in the messages.
Image DecodeWithStb(const std::string& bytes, const fs::path& path, const std::string& format) {
  if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    throw Error(Quoted(path) + " is too large");
  }
  int width = 0;
  int height = 0;
  int channels_in_file = 0;
  // The header first: a small file can declare a huge image ("decompression bomb").
  if (stbi_info_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()),
                            static_cast<int>(bytes.size()), &width, &height,
                            &channels_in_file) == 0) {
    throw Error(Quoted(path) + " is not a readable " + format + " image (" + stbi_failure_reason() +
                ")");
  }
  CheckDeclaredSize(width, height, path, format);
  std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
      stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()),
                            static_cast<int>(bytes.size()), &width, &height, &channels_in_file, 3),
      stbi_image_free);
  if (!pixels) {
    throw Error(Quoted(path) + " is not a readable " + format + " image (" + stbi_failure_reason() +
                ")");
  }
  const stbi_uc* first = pixels.get();
  const std::size_t size = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3;
  return Image(width, height, std::vector<std::uint8_t>(first, first + size));
}

}  // namespace

std::string EncodeImage(const Image& image, const fs::path& name) {
  return ToLower(name.extension().string()) == ".ppm" ? EncodePpm(image) : EncodePng(image);
}

void WriteImage(const Image& image, const fs::path& path) {
  const std::string encoded = EncodeImage(image, path);

  // Write beside the destination, then rename: a failure never leaves a
  // half-written file where the user's old one was.
  fs::path temporary = path;
  temporary += ".partial";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) {
      throw Error("cannot write " + Quoted(path) + ": " + std::strerror(errno));
    }
    out.write(encoded.data(), static_cast<std::streamsize>(encoded.size()));
    out.close();
    if (!out) {
      std::error_code ignored;
      fs::remove(temporary, ignored);
      throw Error("cannot write " + Quoted(path) + ": write failed");
    }
  }
  std::error_code error;
  fs::rename(temporary, path, error);
  if (error) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw Error("cannot write " + Quoted(path) + ": " + error.message());
  }
}

Image ReadImage(const fs::path& path) {
  const std::string bytes = ReadWholeFile(path);
  if (bytes.empty()) {
    throw Error(Quoted(path) + " is empty");
  }
  if (bytes.size() >= 2 && bytes[0] == 'P' && (bytes[1] == '3' || bytes[1] == '6')) {
    return PpmReader(bytes, path).Read();
  }
  if (bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0) {
    return DecodeWithStb(bytes, path, "PNG");
  }
  if (bytes.compare(0, 3, "\xff\xd8\xff") == 0) {
    return DecodeWithStb(bytes, path, "JPEG");
  }
  throw Error(Quoted(path) + " is neither a PNG, a JPEG nor a PPM (P3 or P6) image");
}

}  // namespace cgfs
