// PNG and PPM files: round trips, the formats other programs write, and
// clear errors for bad files.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <vector>

#include <unistd.h>

#include <stb_image_write.h>

#include "program/error.h"
#include "program/image_files.h"
#include "temporary_folder.h"

namespace fs = std::filesystem;
using cgfs::Image;
using cgfs::Rgb8;

namespace {

fs::path TemporaryFolder() {
  return cgfs::test::TemporaryFolder("cgfs-image-io-test");
}

void WriteText(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

Image TestPattern() {
  Image image(7, 5);
  for (int row = 0; row < 5; ++row) {
    for (int column = 0; column < 7; ++column) {
      image.Set(column, row,
                Rgb8{static_cast<std::uint8_t>(column * 36), static_cast<std::uint8_t>(row * 60),
                     static_cast<std::uint8_t>((column + row) % 2 ? 255 : 3)});
    }
  }
  return image;
}

}  // namespace

TEST_CASE("PNG round trip keeps every byte", "[image-io]") {
  const fs::path file = TemporaryFolder() / "pattern.png";
  cgfs::WriteImage(TestPattern(), file);
  CHECK(cgfs::ReadImage(file) == TestPattern());
  CHECK_FALSE(fs::exists(file.string() + ".partial"));
}

TEST_CASE("binary PPM round trip keeps every byte", "[image-io]") {
  const fs::path file = TemporaryFolder() / "pattern.ppm";
  cgfs::WriteImage(TestPattern(), file);
  std::ifstream in(file, std::ios::binary);
  std::string magic(2, ' ');
  in.read(magic.data(), 2);
  CHECK(magic == "P6");
  CHECK(cgfs::ReadImage(file) == TestPattern());
}

TEST_CASE("ASCII PPM with comments and another maximum value", "[image-io]") {
  const fs::path file = TemporaryFolder() / "ascii.ppm";
  WriteText(file,
            "P3\n# written by a student's program\n2 2\n# max\n15\n"
            "15 0 0   0 15 0\n0 0 15  5 10 15\n");
  const Image image = cgfs::ReadImage(file);
  REQUIRE(image.Width() == 2);
  REQUIRE(image.Height() == 2);
  CHECK(image.At(0, 0) == Rgb8{255, 0, 0});
  CHECK(image.At(1, 0) == Rgb8{0, 255, 0});
  CHECK(image.At(0, 1) == Rgb8{0, 0, 255});
  CHECK(image.At(1, 1) == Rgb8{85, 170, 255});
}

TEST_CASE("16-bit binary PPM is scaled to 8 bits", "[image-io]") {
  const fs::path file = TemporaryFolder() / "deep.ppm";
  WriteText(file, std::string("P6 1 1 65535\n\xff\xff\x80\x00\x00\x00", 13 + 6));
  CHECK(cgfs::ReadImage(file).At(0, 0) == Rgb8{255, 128, 0});
}

TEST_CASE("a JPEG is read as RGB", "[image-io]") {
  // A flat orange 16x8 JPEG, written with stb's own encoder: JPEG is lossy, so the
  // colour comes back within a few levels.
  std::string jpeg;
  const std::vector<std::uint8_t> orange = [] {
    std::vector<std::uint8_t> bytes;
    for (int i = 0; i < 16 * 8; ++i) {
      bytes.insert(bytes.end(), {230, 120, 20});
    }
    return bytes;
  }();
  REQUIRE(stbi_write_jpg_to_func(
              [](void* context, void* data, int size) {
                static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                                           static_cast<std::size_t>(size));
              },
              &jpeg, 16, 8, 3, orange.data(), 95) != 0);
  const fs::path file = TemporaryFolder() / "orange.jpg";
  WriteText(file, jpeg);
  const Image image = cgfs::ReadImage(file);
  CHECK(image.Width() == 16);
  CHECK(image.Height() == 8);
  const Rgb8 pixel = image.At(5, 3);
  CHECK(std::abs(pixel.r - 230) <= 4);
  CHECK(std::abs(pixel.g - 120) <= 4);
  CHECK(std::abs(pixel.b - 20) <= 4);
}

TEST_CASE("grey and RGBA PNGs are read as RGB", "[image-io]") {
  // 3 x 2 pixels of 1 (grey), 2 (grey and alpha) and 4 (RGBA) channels, written with
  // stb's encoder: every one comes back as three channels, the alpha dropped.
  const std::vector<std::uint8_t> levels = {0, 40, 80, 120, 160, 255};
  for (const int channels : {1, 2, 4}) {
    std::vector<std::uint8_t> bytes;
    for (const std::uint8_t level : levels) {
      if (channels <= 2) {
        bytes.push_back(level);
      } else {
        bytes.insert(bytes.end(), {level, static_cast<std::uint8_t>(255 - level), 7});
      }
      if (channels % 2 == 0) {
        bytes.push_back(100);  // alpha
      }
    }
    std::string png;
    REQUIRE(stbi_write_png_to_func(
                [](void* context, void* data, int size) {
                  static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                                             static_cast<std::size_t>(size));
                },
                &png, 3, 2, channels, bytes.data(), 3 * channels) != 0);
    const fs::path file = TemporaryFolder() / "channels.png";
    WriteText(file, png);
    const Image image = cgfs::ReadImage(file);
    CAPTURE(channels);
    REQUIRE(image.Width() == 3);
    REQUIRE(image.Height() == 2);
    for (int i = 0; i < 6; ++i) {
      const std::uint8_t level = levels[static_cast<std::size_t>(i)];
      const Rgb8 expected = channels <= 2 ? Rgb8{level, level, level}
                                          : Rgb8{level, static_cast<std::uint8_t>(255 - level), 7};
      CHECK(image.At(i % 3, i / 3) == expected);
    }
  }
}

TEST_CASE("writing replaces an existing file", "[image-io]") {
  const fs::path file = TemporaryFolder() / "pattern.png";
  WriteText(file, "old contents");
  cgfs::WriteImage(TestPattern(), file);
  CHECK(cgfs::ReadImage(file) == TestPattern());
}

TEST_CASE("bad image files are refused with one-line errors", "[image-io]") {
  const fs::path folder = TemporaryFolder();
  auto message_for = [](const fs::path& path) {
    try {
      cgfs::ReadImage(path);
    } catch (const cgfs::Error& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };

  CHECK_THAT(message_for(folder / "missing.png"), Catch::Contains("cannot read"));
  CHECK_THAT(message_for(folder), Catch::Contains("directory"));

  WriteText(folder / "empty.png", "");
  CHECK_THAT(message_for(folder / "empty.png"), Catch::Contains("empty"));

  WriteText(folder / "text.png", "this is not an image at all");
  CHECK_THAT(message_for(folder / "text.png"), Catch::Contains("neither a PNG, a JPEG nor a PPM"));

  WriteText(folder / "short.ppm", "P6\n4 4\n255\nabc");
  CHECK_THAT(message_for(folder / "short.ppm"), Catch::Contains("ends after 3 of 48 pixel bytes"));

  // Long enough in bytes to hold 2x1 pixels, but only four samples.
  WriteText(folder / "short-ascii.ppm", "P3\n2 1\n255\n1 2 3 4          \n");
  CHECK_THAT(message_for(folder / "short-ascii.ppm"),
             Catch::Contains("the file ends before the pixel value"));

  // Too few bytes for the declared size: refused before any pixel is allocated.
  WriteText(folder / "tiny-ascii.ppm", "P3\n4096 4096\n255\n1 2 3\n");
  CHECK_THAT(message_for(folder / "tiny-ascii.ppm"),
             Catch::Contains("too short for 4096x4096 pixels"));

  WriteText(folder / "huge.ppm", "P3 32768 32768 255\n");
  CHECK_THAT(message_for(folder / "huge.ppm"), Catch::Contains("32768x32768 is out of range"));

  WriteText(folder / "big-sample.ppm", "P3\n1 1\n255\n1 256 3\n");
  CHECK_THAT(message_for(folder / "big-sample.ppm"), Catch::Contains("exceeds the maximum"));

  WriteText(folder / "huge.ppm", "P3\n99999999999 1\n255\n");
  CHECK_THAT(message_for(folder / "huge.ppm"), Catch::Contains("too large"));

  // A truncated PNG: the real header, then nothing.
  cgfs::WriteImage(TestPattern(), folder / "whole.png");
  std::ifstream whole(folder / "whole.png", std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(whole)), std::istreambuf_iterator<char>());
  WriteText(folder / "truncated.png", bytes.substr(0, bytes.size() / 2));
  CHECK_THAT(message_for(folder / "truncated.png"), Catch::Contains("not a readable PNG"));

  // A JPEG that stops after its first marker, and one whose header declares a
  // 30000x30000 image: both refused, the second before anything is decoded.
  WriteText(folder / "truncated.jpg", std::string("\xff\xd8\xff\xe0", 4));
  CHECK_THAT(message_for(folder / "truncated.jpg"), Catch::Contains("not a readable JPEG"));
  WriteText(folder / "huge.jpg",
            std::string("\xff\xd8"                                  // start of image
                        "\xff\xc0\x00\x11\x08\x75\x30\x75\x30\x03"  // 30000x30000, 3 parts
                        "\x01\x11\x00\x02\x11\x00\x03\x11\x00"
                        "\xff\xda\x00\x0c\x03\x01\x00\x02\x11\x03\x11\x00\x3f\x00"  // start of scan
                        "\xff\xd9",                                                 // end of image
                        37));
  CHECK_THAT(message_for(folder / "huge.jpg"), Catch::Contains("30000x30000 is out of range"));

  for (const std::string& message :
       {message_for(folder / "text.png"), message_for(folder / "short-ascii.ppm")}) {
    CHECK(message.find('\n') == std::string::npos);
  }
}

TEST_CASE("an unwritable path is an error, and leaves nothing behind", "[image-io]") {
  const fs::path folder = TemporaryFolder();
  CHECK_THROWS_AS(cgfs::WriteImage(TestPattern(), folder / "no-such-folder" / "x.png"),
                  cgfs::Error);
  CHECK(fs::is_empty(folder));
}
