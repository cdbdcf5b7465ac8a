// The chapter's figures, pixel by pixel and as whole images.
#include <catch2/catch.hpp>

#include <algorithm>

#include "golden.h"
#include "pixels.h"
#include "printing.h"
#include "scenes.h"

using cgfs::Rgb8;
using cgfs::test::ChangedPixels;
using cgfs::test::CheckAgainstGolden;
using cgfs::test::RenderFigureNamed;

namespace {

// The darkest and brightest red over a grid of pixels inside Figure 14-11's square.
std::pair<int, int> RangeOnTheSquare(const Canvas& canvas) {
  int darkest = 255;
  int brightest = 0;
  for (int x = -180; x < -90; x += 10) {
    for (int y = 70; y < 150; y += 10) {
      darkest = std::min(darkest, int{canvas.GetPixel(x, y).r});
      brightest = std::max(brightest, int{canvas.GetPixel(x, y).r});
    }
  }
  return {darkest, brightest};
}

}  // namespace

TEST_CASE("a textured strip: affine u is off at the screen midpoint, u/z is right", "[figures]") {
  // The segment of the book's example, A = (-1, 0, 2) with u = 0 and B = (1, 0, 10)
  // with u = 1, widened into a strip; the texture is black for u < 0.5, white beyond.
  // At pixel x = -100, u is 0.2 (black); linear interpolation on the canvas says 0.556.
  static const MipmappedTexture halves =
      BuildMipChain(Texture{2, 1, {Color(0, 0, 0), Color(255, 255, 255)}});
  static const Model strip = [] {
    const std::array<Vec3, 3> N = {Vec3(0, 0, -1), Vec3(0, 0, -1), Vec3(0, 0, -1)};
    Model model;
    model.vertices = {{-1, -0.2, 2}, {1, -0.2, 10}, {1, 0.2, 10}, {-1, 0.2, 2}};
    model.triangles = {
        {{0, 1, 2}, cgfs::kWhite, N, {glm::dvec2(0, 0), glm::dvec2(1, 0), glm::dvec2(1, 1)}},
        {{0, 2, 3}, cgfs::kWhite, N, {glm::dvec2(0, 0), glm::dvec2(1, 1), glm::dvec2(0, 1)}}};
    model.closed = false;
    model.texture = &halves;
    return model;
  }();
  Scene scene;
  scene.instances = {{&strip, {}}};
  scene.lights = {{LightType::kAmbient, 1}};
  for (const auto& [interpolation, expected] :
       {std::pair{TextureInterpolation::kPerspectiveCorrect, 0},
        std::pair{TextureInterpolation::kAffine, 255}}) {
    Shading shading;
    shading.texturing = {interpolation, TextureFilter::kNearest};
    Canvas canvas(600, 600);
    RenderScene(scene, canvas, shading);
    CHECK(int{canvas.GetPixel(-100, 0).r} == expected);
  }
}

TEST_CASE("figures 14-3 and 14-5 differ inside the faces, not in their outlines", "[figures]") {
  const Canvas affine = RenderFigureNamed(Figures({}), "fig-14-3-affine");
  const Canvas correct = RenderFigureNamed(Figures({}), "fig-14-5-perspective-correct");
  CHECK(ChangedPixels(affine, correct).size() > 10000);
  // The same pixels are covered: only the texture moves.
  CHECK(cgfs::test::DrawnPixels(affine) == cgfs::test::DrawnPixels(correct));
}

TEST_CASE("figure 14-11: the small checkerboard is grey only with mipmaps", "[figures]") {
  const auto range = [](const char* figure) {
    return RangeOnTheSquare(RenderFigureNamed(Figures({}), figure));
  };
  CHECK(range("fig-14-11-minified-nearest") == std::pair{0, 255});  // black and white
  const auto [bilinear_low, bilinear_high] = range("minified-bilinear");
  CHECK(bilinear_high - bilinear_low > 100);               // patterns
  CHECK(range("minified-mipmap") == std::pair{128, 128});  // level 1, 127.5 everywhere
  const auto [trilinear_low, trilinear_high] = range("minified-trilinear");
  CHECK(trilinear_low >= 124);
  CHECK(trilinear_high <= 131);
}

TEST_CASE("figures 14-7 and 14-8: nearest shows the texels, bilinear blends them", "[figures]") {
  const Canvas nearest = RenderFigureNamed(Figures({}), "fig-14-7-close-up-nearest");
  const Canvas bilinear = RenderFigureNamed(Figures({}), "fig-14-8-close-up-bilinear");
  // Along a row, nearest changes colour only at texel edges, every 10 pixels or so;
  // bilinear changes at almost every pixel.
  int nearest_changes = 0;
  int bilinear_changes = 0;
  for (int x = -150; x < 150; ++x) {
    nearest_changes += nearest.GetPixel(x, 0) != nearest.GetPixel(x + 1, 0);
    bilinear_changes += bilinear.GetPixel(x, 0) != bilinear.GetPixel(x + 1, 0);
  }
  CHECK(nearest_changes < 60);
  CHECK(bilinear_changes > 150);
}

TEST_CASE("fig-14-3-affine matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "fig-14-3-affine");
}

TEST_CASE("fig-14-5-perspective-correct matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "fig-14-5-perspective-correct");
}

TEST_CASE("fig-14-7-close-up-nearest matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "fig-14-7-close-up-nearest");
}

TEST_CASE("fig-14-8-close-up-bilinear matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "fig-14-8-close-up-bilinear");
}

TEST_CASE("fig-14-11-minified-nearest matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "fig-14-11-minified-nearest");
}

TEST_CASE("minified-bilinear matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "minified-bilinear");
}

TEST_CASE("minified-mipmap matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "minified-mipmap");
}

TEST_CASE("minified-trilinear matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "minified-trilinear");
}

TEST_CASE("fig-14-12-mip-chain matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "fig-14-12-mip-chain");
}

TEST_CASE("crates-trilinear matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "crates-trilinear");
}

TEST_CASE("crates-trilinear-mip-levels matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "crates-trilinear-mip-levels");
}
