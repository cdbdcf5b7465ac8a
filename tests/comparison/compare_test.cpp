// The image comparison behind the golden tests and the student tool.
#include <stdexcept>

#include <catch2/catch.hpp>

#include "comparison/compare.h"

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
  // Both images have something drawn there (no background): "in both, another colour".
  CHECK(result.recoloured_pixels == 100);
  const Rgb8 marked = result.difference.At(55, 205);
  CHECK_FALSE((marked.r == marked.g && marked.g == marked.b));  // not the faded grey
  CHECK(result.difference.At(0, 0) != marked);
  CHECK_THAT(cgfs::Describe(result, 600, 600),
             Catch::Contains("FAIL: 100 of 360000") && Catch::Contains("canvas (-250, 99)"));
}

TEST_CASE("the first differing pixel is the first in reading order, with both colours",
          "[compare]") {
  const Image expected(600, 600, Rgb8{255, 255, 255});
  Image actual = expected;
  actual.Set(400, 300, Rgb8{10, 20, 30});  // lower, but further left than...
  actual.Set(450, 120, Rgb8{0, 0, 255});   // ...this one, which comes first
  const auto result = cgfs::CompareImages(expected, actual);
  CHECK(result.first_differing.column == 450);
  CHECK(result.first_differing.row == 120);
  CHECK(result.first_differing.yours == Rgb8{0, 0, 255});
  CHECK(result.first_differing.ours == Rgb8{255, 255, 255});
  CHECK_THAT(cgfs::Describe(result, 600, 600),
             Catch::Contains("first differing pixel: (450, 120) = canvas (150, 179): "
                             "yours (0, 0, 255), ours (255, 255, 255)"));
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

TEST_CASE("a channel two levels off is the same pixel, three levels off differs", "[compare]") {
  const Image expected = Gradient(600, 600);
  for (const int levels : {-2, 2, -3, 3}) {
    Image actual = expected;
    Rgb8 pixel = actual.At(300, 300);
    pixel.g = static_cast<std::uint8_t>(pixel.g + levels);
    actual.Set(300, 300, pixel);
    CAPTURE(levels);
    CHECK(cgfs::CompareImages(expected, actual).differing_pixels == (std::abs(levels) > 2 ? 1 : 0));
  }
}

TEST_CASE("the budget of differing pixels is rounded down where it is not whole", "[compare]") {
  // 640 x 480 x 0.0001 = 30.72 pixels: 30 may differ, not 31.
  const Image expected = Gradient(640, 480);
  CHECK(cgfs::Tolerance{}.AllowedDifferingPixels(640 * 480) == 30);
  Image actual = expected;
  for (int i = 0; i < 31; ++i) {
    Rgb8 pixel = actual.At(i, 1);
    pixel.r = static_cast<std::uint8_t>(pixel.r > 127 ? pixel.r - 10 : pixel.r + 10);
    actual.Set(i, 1, pixel);
    CHECK(cgfs::CompareImages(expected, actual).passed == (i + 1 <= 30));
  }
}

TEST_CASE("images of different sizes cannot be compared", "[compare]") {
  CHECK_THROWS_AS(cgfs::CompareImages(Image(600, 600), Image(600, 598)), std::invalid_argument);
}

namespace {

// A white 100x100 image with a black 30x20 rectangle whose top-left pixel is (x, y).
Image Rectangle(int x, int y) {
  Image image(100, 100, Rgb8{255, 255, 255});
  for (int row = y; row < y + 20; ++row) {
    for (int column = x; column < x + 30; ++column) {
      image.Set(column, row, Rgb8{0, 0, 0});
    }
  }
  return image;
}

}  // namespace

TEST_CASE("differing pixels are told apart: in ours only, in yours only, recoloured", "[compare]") {
  Image actual = Rectangle(10, 10);
  actual.Set(90, 90, Rgb8{0, 0, 0});        // extra
  actual.Set(10, 10, Rgb8{255, 255, 255});  // missing
  actual.Set(11, 10, Rgb8{0, 200, 0});      // recoloured
  const auto result = cgfs::CompareImages(Rectangle(10, 10), actual);
  CHECK(result.extra_pixels == 1);
  CHECK(result.missing_pixels == 1);
  CHECK(result.recoloured_pixels == 1);
  CHECK(result.difference.At(90, 90) != result.difference.At(10, 10));
  CHECK(result.difference.At(11, 10) != result.difference.At(10, 10));
}

TEST_CASE("a background of another colour is recoloured, not drawn in yours only", "[compare]") {
  const Image ours = Rectangle(10, 10);
  Image darker(100, 100, Rgb8{128, 128, 128});  // ours at half brightness: the shapes agree
  for (int row = 10; row < 30; ++row) {
    for (int column = 10; column < 40; ++column) {
      darker.Set(column, row, Rgb8{0, 0, 0});
    }
  }
  const auto result = cgfs::CompareImages(ours, darker);
  CHECK(result.differing_pixels == 100 * 100 - 30 * 20);
  CHECK(result.recoloured_pixels == result.differing_pixels);
  CHECK(result.extra_pixels == 0);
  CHECK(result.missing_pixels == 0);
}

TEST_CASE(
    "a picture moved by one pixel, flipped, with red and blue swapped or on another background is "
    "diagnosed in words",
    "[compare]") {
  const Image ours = Rectangle(10, 10);
  CHECK_THAT(cgfs::CompareImages(ours, Rectangle(10, 11)).diagnosis,
             Catch::Contains("moved one row down") && Catch::Contains("Sy"));
  CHECK_THAT(cgfs::CompareImages(ours, Rectangle(10, 9)).diagnosis,
             Catch::Contains("moved one row up"));
  CHECK_THAT(cgfs::CompareImages(ours, Rectangle(11, 10)).diagnosis,
             Catch::Contains("moved one column right") && Catch::Contains("Sx"));
  CHECK_THAT(cgfs::CompareImages(ours, Rectangle(9, 10)).diagnosis,
             Catch::Contains("moved one column left"));
  CHECK_THAT(cgfs::CompareImages(ours, Rectangle(10, 70)).diagnosis,
             Catch::Contains("upside down"));
  // Our row r drawn at row 98 - r: canvas y negated.
  CHECK_THAT(cgfs::CompareImages(ours, Rectangle(10, 69)).diagnosis,
             Catch::Contains("upside down about canvas y = 0"));
  CHECK_THAT(cgfs::CompareImages(ours, Rectangle(60, 10)).diagnosis,
             Catch::Contains("mirrored left to right"));
  Image blue_and_red = Rectangle(10, 10);
  Image red_and_blue = Rectangle(10, 10);
  for (int i = 50; i < 60; ++i) {
    blue_and_red.Set(i, i, Rgb8{200, 30, 10});
    red_and_blue.Set(i, i, Rgb8{10, 30, 200});
  }
  CHECK_THAT(cgfs::CompareImages(blue_and_red, red_and_blue).diagnosis,
             Catch::Contains("red and blue swapped"));
  Image on_black = Rectangle(10, 10);
  for (int row = 0; row < 100; ++row) {
    for (int column = 0; column < 100; ++column) {
      if (on_black.At(column, row) == Rgb8{255, 255, 255}) {
        on_black.Set(column, row, Rgb8{0, 0, 40});
      }
    }
  }
  CHECK(cgfs::CompareImages(ours, on_black).diagnosis ==
        "only the background differs: yours is (0, 0, 40), ours (255, 255, 255); check the "
        "background colour");
  // Moved by more than a pixel: no diagnosis, only the numbers.
  CHECK(cgfs::CompareImages(ours, Rectangle(10, 30)).diagnosis.empty());
  // A match needs none.
  CHECK(cgfs::CompareImages(ours, ours).diagnosis.empty());
}

TEST_CASE("a picture darker or brighter by one factor or one number of levels is diagnosed",
          "[compare]") {
  const Image ours = Gradient(100, 100);  // channels 10..209 and 128
  const auto recoloured = [&](auto change) {
    Image image = ours;
    for (int row = 0; row < 100; ++row) {
      for (int column = 0; column < 100; ++column) {
        const Rgb8 p = ours.At(column, row);
        image.Set(column, row, Rgb8{change(p.r), change(p.g), change(p.b)});
      }
    }
    return image;
  };
  const auto level = [](double value) {
    return static_cast<std::uint8_t>(std::clamp(std::lround(value), 0L, 255L));
  };
  CHECK(cgfs::CompareImages(ours, recoloured([&](int c) { return level(c * 0.8); })).diagnosis ==
        "your image is ours with every channel times 0.8 (darker): check how colours become "
        "0-255 levels, and the lights' intensities");
  CHECK_THAT(
      cgfs::CompareImages(ours, recoloured([&](int c) { return level(c * 1.25); })).diagnosis,
      Catch::StartsWith("your image is ours with every channel times 1.25 (brighter)"));
  CHECK(cgfs::CompareImages(ours, recoloured([&](int c) { return level(c + 20); })).diagnosis ==
        "your image is ours 20 levels brighter everywhere: check how colours become 0-255 levels");
  CHECK_THAT(cgfs::CompareImages(ours, recoloured([&](int c) { return level(c - 7); })).diagnosis,
             Catch::StartsWith("your image is ours 7 levels darker everywhere"));
  // Darker in one half only is not a change of brightness.
  Image half = ours;
  for (int row = 0; row < 50; ++row) {
    for (int column = 0; column < 100; ++column) {
      half.Set(column, row, Rgb8{0, 0, 0});
    }
  }
  CHECK(cgfs::CompareImages(ours, half).diagnosis.empty());
}
