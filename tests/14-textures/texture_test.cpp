// "Painting a Crate", "Bilinear Filtering", "Mipmapping", "Trilinear Filtering".
#include <catch2/catch.hpp>

#include <cmath>

#include "cases.h"
#include "checks.h"
#include "scenes.h"

using Catch::Detail::Approx;
using cgfs::test::CheckNear;

namespace {

// A texture of `width` x `height` whose texels are the given grey levels, row by row.
// {"width": w, "height": h, "texels": [[r, g, b], ...] row by row from the top}.
Texture TextureOfCase(const nlohmann::json& texture) {
  Texture result{texture.at("width").get<int>(), texture.at("height").get<int>(), {}};
  for (const nlohmann::json& texel : texture.at("texels")) {
    result.texels.push_back(cgfs::test::ToColor(texel));
  }
  return result;
}

Texture Greys(int width, int height, std::vector<double> levels) {
  Texture texture{width, height, {}};
  for (const double level : levels) {
    texture.texels.push_back({level, level, level});
  }
  return texture;
}

long long TexelCount(const MipmappedTexture& chain) {
  long long count = 0;
  for (const Texture& level : chain.levels) {
    count += static_cast<long long>(level.width) * level.height;
  }
  return count;
}

}  // namespace

TEST_CASE("u and v are not linear on the canvas, u/z and v/z are", "[texture]") {
  // A = (-1, 0, 2) with u = 0, B = (1, 0, 10) with u = 1, d = 1: A' = -300 pixels,
  // B' = 60. The screen midpoint x' = -0.2 (pixel -120) is 180 of the 360 pixels from A'
  // to B'. What each corner carries, carried halfway as the triangle walker carries it,
  // and the (u, v) a pixel gets back from it:
  const auto u_halfway = [](TextureInterpolation interpolation) {
    Texturing texturing;
    texturing.interpolation = interpolation;
    Attributes A;
    A.inv_z = 1.0 / 2;
    A.uv = CarriedTextureCoordinates({0, 0}, 2, texturing);
    Attributes B;
    B.inv_z = 1.0 / 10;
    B.uv = CarriedTextureCoordinates({1, 0}, 10, texturing);
    const Attributes halfway = A + (B - A) / 360.0 * 180.0;
    return std::pair(TextureCoordinates(halfway, texturing).x, halfway);
  };
  CHECK(u_halfway(TextureInterpolation::kAffine).first == Approx(0.5));  // wrong
  const auto [u, carried] = u_halfway(TextureInterpolation::kPerspectiveCorrect);
  CHECK(carried.uv.x == Approx(0.05));           // u/z
  CHECK(carried.inv_z == Approx(0.3));           // 1/z
  CHECK(u == Approx(0.166667));                  // right
  CHECK(1 / carried.inv_z == Approx(3.333333));  // the true depth there
}

TEST_CASE("GetTexelNearest: the cases of 14-textures.json", "[texture]") {
  for (const cgfs::test::FunctionCase& c :
       cgfs::test::CasesOf("14-textures.json", "GetTexelNearest")) {
    INFO(c.Describe());
    const Color texel =
        GetTexelNearest(TextureOfCase(c.args.at("texture")), cgfs::test::ToNumber(c.args.at("tx")),
                        cgfs::test::ToNumber(c.args.at("ty")));
    CHECK_THAT(cgfs::test::AsNumbers(texel), cgfs::test::MatchesCase(c));
  }
}

TEST_CASE("GetTexel: the cases of 14-textures.json", "[texture]") {
  for (const cgfs::test::FunctionCase& c : cgfs::test::CasesOf("14-textures.json", "GetTexel")) {
    INFO(c.Describe());
    const Color texel =
        GetTexel(TextureOfCase(c.args.at("texture")), cgfs::test::ToNumber(c.args.at("tx")),
                 cgfs::test::ToNumber(c.args.at("ty")));
    CHECK_THAT(cgfs::test::AsNumbers(texel), cgfs::test::MatchesCase(c));
  }
}

TEST_CASE("GetTexelNearest: floor(u w), clamped to the last texel", "[texture]") {
  // Texel i has grey level i.
  std::vector<double> columns;
  for (int i = 0; i < 600; ++i) {
    columns.push_back(i);
  }
  const Texture texture = Greys(600, 1, columns);
  CHECK(GetTexelNearest(texture, 0.5 * 600, 0).r == 300);
  CHECK(GetTexelNearest(texture, 1.0 * 600, 0).r == 599);  // u = 1: one past the last
  CHECK(GetTexelNearest(texture, 0, 0).r == 0);
  CHECK(GetTexelNearest(texture, -3, 0).r == 0);
}

TEST_CASE("GetTexel: bilinear filtering, the book's example", "[texture]") {
  // TL = 0, TR = 100, BL = 50, BR = 250; fx = 0.25, fy = 0.5: CT = 25, CB = 100, 62.5.
  const Texture texture = Greys(2, 2, {0, 100, 50, 250});
  CHECK(GetTexel(texture, 0.25, 0.5).r == Approx(62.5));
  CHECK(GetTexel(texture, 0, 0).r == 0);    // TL
  CHECK(GetTexel(texture, 1, 0).r == 100);  // TR
  CHECK(GetTexel(texture, 0.999999, 0).r == Approx(100).margin(1e-3));
  CHECK(GetTexel(texture, 1.5, 1.5).r == 250);  // past the last row and column: BR again
}

TEST_CASE("BuildMipChain: 256x256 gives 9 levels, 87 381 texels, 4/3 of the first", "[mipmap]") {
  const MipmappedTexture chain =
      BuildMipChain(MakeCheckerboard(256, 1, cgfs::kBlack, cgfs::kWhite));
  REQUIRE(chain.levels.size() == 9);
  for (std::size_t k = 0; k < 9; ++k) {
    CHECK(chain.levels[k].width == 256 >> k);
    CHECK(chain.levels[k].height == 256 >> k);
  }
  CHECK(TexelCount(chain) == 87381);
  CHECK(static_cast<double>(TexelCount(chain)) / 65536 == Approx(4.0 / 3).epsilon(1e-4));
  // A one-texel checkerboard: every 2x2 block is two black and two white texels.
  for (const Color& texel : chain.levels[1].texels) {
    CHECK(texel == Color(127.5, 127.5, 127.5));
  }
}

TEST_CASE("BuildMipChain: sizes that are not powers of two", "[mipmap]") {
  // 600 -> 300 -> 150 -> 75 -> 37 -> 18 -> 9 -> 4 -> 2 -> 1.
  const MipmappedTexture chain =
      BuildMipChain(MakeCheckerboard(600, 3, cgfs::kBlack, cgfs::kWhite));
  std::vector<int> widths;
  for (const Texture& level : chain.levels) {
    widths.push_back(level.width);
  }
  CHECK(widths == std::vector<int>{600, 300, 150, 75, 37, 18, 9, 4, 2, 1});
  // 3x2: one level down is 1x1, the average of the first 2x2 block.
  const MipmappedTexture small = BuildMipChain(Greys(3, 2, {0, 40, 200, 80, 120, 200}));
  REQUIRE(small.levels.size() == 2);
  CHECK(small.levels[1].texels[0].r == Approx(60));
}

TEST_CASE("MipLevel and the samplers for rho = 10", "[mipmap]") {
  // A chain whose level k is uniformly 10 k grey.
  MipmappedTexture chain;
  for (int k = 0; k < 9; ++k) {
    chain.levels.push_back(Greys(1, 1, {10.0 * k}));
  }
  CHECK(MipLevel(10, chain) == Approx(3.321928));
  CHECK(MipLevel(0.5, chain) == 0);  // magnified: the full-size texture
  CHECK(MipLevel(1e6, chain) == 8);  // beyond the last level: the last
  // Mipmapping: the nearest level, 3 (8 times smaller). Trilinear: 0.3219 of the way
  // from level 3 to level 4.
  CHECK(SampleTexture(chain, 0.5, 0.5, 10, TextureFilter::kMipmap).r == Approx(30));
  CHECK(SampleTexture(chain, 0.5, 0.5, 10, TextureFilter::kTrilinear).r == Approx(33.21928));
  CHECK(SampleTexture(chain, 0.5, 0.5, 10, TextureFilter::kBilinear).r == 0);
  CHECK(SampleTexture(chain, 0.5, 0.5, 10, TextureFilter::kNearest).r == 0);
}

TEST_CASE("TexelsPerPixel: the faster of the two directions, in texels", "[mipmap]") {
  const Texture texture = MakeCheckerboard(256, 1, cgfs::kBlack, cgfs::kWhite);
  // 256 texels over 128 pixels: 2 texels per pixel.
  CHECK(TexelsPerPixel({1.0 / 128, 0}, {0, 1.0 / 128}, texture) == Approx(2));
  CHECK(TexelsPerPixel({1.0 / 128, 0}, {0, 1.0 / 16}, texture) == Approx(16));
  CHECK(TexelsPerPixel({3.0 / 256, 4.0 / 256}, {0, 0}, texture) == Approx(5));
}

TEST_CASE("every mip level is read at the same place of the texture", "[mipmap]") {
  // A ramp: texel (i, j) is (i, j, 0). Averaging 2x2 blocks keeps it a ramp, so every
  // level, read where it should be, gives the book's level-0 value at (u, v): u * 256
  // in red, v * 256 in green. A level read at (u w', v h') would be off by half a block
  // minus half a texel: 3.5 on level 3.
  Texture ramp{256, 256, {}};
  for (int j = 0; j < 256; ++j) {
    for (int i = 0; i < 256; ++i) {
      ramp.texels.push_back(Color(i, j, 0));
    }
  }
  const MipmappedTexture chain = BuildMipChain(std::move(ramp));
  for (const double u : {0.3, 0.5123, 0.7}) {
    for (int level = 0; level <= 5; ++level) {
      const double rho = std::pow(2.0, level);  // mipmapping picks this level
      const Color texel = SampleTexture(chain, u, 1 - u, rho, TextureFilter::kMipmap);
      INFO("u " << u << ", level " << level);
      CHECK(texel.r == Approx(u * 256).margin(1e-9));
      CHECK(texel.g == Approx((1 - u) * 256).margin(1e-9));
    }
  }
}
