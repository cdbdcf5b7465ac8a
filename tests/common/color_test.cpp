// Colour arithmetic, and clamp-then-round on write.
#include <catch2/catch.hpp>

#include "cgfs/canvas.h"
#include "cgfs/color.h"

using cgfs::Color;
using cgfs::Rgb8;

TEST_CASE("colours scale and add channel by channel", "[color]") {
  CHECK(2.0 * Color(16, 0, 64) == Color(32, 0, 128));
  CHECK(Color(255, 0, 0) + Color(0, 255, 0) == Color(255, 255, 0));
  CHECK(0.25 * Color(200, 100, 40) == Color(50, 25, 10));
}

TEST_CASE("intermediate colours may leave 0..255 and are clamped only when written", "[color]") {
  const Color raw = 2.0 * Color(192, 64, 32);
  CHECK(raw == Color(384, 128, 64));
  cgfs::Canvas canvas(2, 2);
  canvas.PutPixel(0, 0, raw);
  CHECK(canvas.GetPixel(0, 0) == Rgb8{255, 128, 64});
}

TEST_CASE("a channel is clamped to 0..255, then rounded to nearest", "[color]") {
  CHECK(cgfs::ToChannel(-20) == 0);
  CHECK(cgfs::ToChannel(0.49) == 0);
  CHECK(cgfs::ToChannel(12.4) == 12);
  CHECK(cgfs::ToChannel(12.6) == 13);
  CHECK(cgfs::ToChannel(112.577) == 113);
  CHECK(cgfs::ToChannel(254.6) == 255);
  CHECK(cgfs::ToChannel(296.02) == 255);
}
