// The image comparison behind the golden tests and the student tool.
#include <catch2/catch.hpp>

#include "cgfs/compare.h"
#include "cgfs/error.h"

using cgfs::Image;
using cgfs::Rgb8;

namespace {

Image Gradient(int width, int height) {
  Image image(width, height);
  for (int row = 0; row < height; ++row) {
    for (int column = 0; column < width; ++column) {
      image.Set(column, row,
                Rgb8{static_cast<std::uint8_t>(10 + column % 200),
                     static_cast<std::uint8_t>(10 + row % 200), 128});
    }
  }
  return image;
}

}  // namespace

TEST_CASE("identical images pass with no changed pixel", "[compare]") {
  const auto result = cgfs::CompareImages(Gradient(600, 600), Gradient(600, 600));
  CHECK(result.passed);
  CHECK(result.changed_pixels == 0);
  CHECK(result.differing_pixels == 0);
  CHECK(result.max_channel_difference == 0);
  CHECK(result.mean_channel_difference == 0);
}

TEST_CASE("a one-level difference everywhere passes", "[compare]") {
  const Image expected = Gradient(600, 600);
  Image actual = expected;
  for (int row = 0; row < 600; ++row) {
    for (int column = 0; column < 600; ++column) {
      Rgb8 pixel = actual.At(column, row);
      pixel.g = static_cast<std::uint8_t>(pixel.g + 1);
      actual.Set(column, row, pixel);
    }
  }
  const auto result = cgfs::CompareImages(expected, actual);
  CHECK(result.passed);
  CHECK(result.changed_pixels == 600 * 600);
  CHECK(result.differing_pixels == 0);
  CHECK(result.max_channel_difference == 1);
  CHECK(result.mean_channel_difference == Approx(1.0 / 3));
}

TEST_CASE("a changed 10x10 block fails and is counted exactly", "[compare]") {
  const Image expected = Gradient(600, 600);
  Image actual = expected;
  for (int row = 200; row < 210; ++row) {
    for (int column = 50; column < 60; ++column) {
      actual.Set(column, row, Rgb8{0, 0, 0});
    }
  }
  const auto result = cgfs::CompareImages(expected, actual);
  CHECK_FALSE(result.passed);
  CHECK(result.differing_pixels == 100);
  CHECK(result.changed_pixels == 100);
  CHECK(result.allowed_differing_pixels == 36);
  CHECK(result.first_column == 50);
  CHECK(result.last_column == 59);
  CHECK(result.first_row == 200);
  CHECK(result.last_row == 209);
  CHECK(result.difference.At(55, 205) == Rgb8{255, 0, 0});
  CHECK(result.difference.At(0, 0) != Rgb8{255, 0, 0});
  CHECK_THAT(cgfs::Describe(result, 600, 600),
             Catch::Contains("FAIL: 100 of 360000") && Catch::Contains("canvas (-250, 99)"));
}

TEST_CASE("the tolerance is a budget of pixels beyond a few levels", "[compare]") {
  const Image expected = Gradient(600, 600);
  Image actual = expected;
  // Three levels off is beyond the channel tolerance; 36 such pixels are allowed, 37 are not.
  for (int i = 0; i < 37; ++i) {
    Rgb8 pixel = actual.At(i, 0);
    pixel.b = static_cast<std::uint8_t>(pixel.b + 3);
    actual.Set(i, 0, pixel);
    const auto result = cgfs::CompareImages(expected, actual);
    CHECK(result.differing_pixels == i + 1);
    CHECK(result.passed == (i + 1 <= 36));
  }
}

TEST_CASE("images of different sizes cannot be compared", "[compare]") {
  CHECK_THROWS_AS(cgfs::CompareImages(Image(600, 600), Image(600, 598)), cgfs::Error);
}
