// Texture mapping against an independent ray caster (tests/support): which texel each
// pixel shows, and how many texels a pixel covers. Textures whose texels say where
// they are, or which mip level they belong to, make the figures readable. Chapter 15
// keeps the texturing and runs this test too.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <optional>

#include "cast_uv.h"
#include "figure_checks.h"
#include "scenes.h"

using cgfs::test::Agreement;
using cgfs::test::CastCamera;
using cgfs::test::CastCameraImage;
using cgfs::test::CastCameraOf;
using cgfs::test::CastHit;
using cgfs::test::CastImage;
using cgfs::test::CastScene;
using cgfs::test::CastSceneOf;
using cgfs::test::CastUV;
using cgfs::test::Describe;
using cgfs::test::LabelImage;
using cgfs::test::LabelsOf;

namespace {

// A 64 x 64 texture whose texel (i, j) is (4i, 4j, 128): a pixel says which texel it shows.
const MipmappedTexture& CoordinateTexture() {
  static const MipmappedTexture texture = [] {
    Texture coordinates{64, 64, {}};
    for (int j = 0; j < 64; ++j) {
      for (int i = 0; i < 64; ++i) {
        coordinates.texels.push_back(Color(4 * i, 4 * j, 128));
      }
    }
    return BuildMipChain(coordinates);
  }();
  return texture;
}

Shading TexturingOf(TextureInterpolation interpolation, TextureFilter filter) {
  Shading shading;
  shading.texturing.interpolation = interpolation;
  shading.texturing.filter = filter;
  return shading;
}

// The texels rays hit around canvas point (x, y), on the same face: the rasteriser
// truncates the ends of its rows and its corners toward zero, so a pixel shows what
// lies up to a pixel away from its point. The range of columns and of rows.
struct TexelRange {
  int i_min = 1 << 30, i_max = -(1 << 30), j_min = 1 << 30, j_max = -(1 << 30);
};
TexelRange TexelsAround(const Scene& scene, const CastScene& cast_scene, const CastCamera& camera,
                        int x, int y, int face) {
  TexelRange range;
  for (const double dx : {-1.25, 0.0, 1.25}) {
    for (const double dy : {-1.25, 0.0, 1.25}) {
      const glm::dvec3 D =
          camera.orientation * glm::dvec3((x + dx) / 600, (y + dy) / 600, camera.distance);
      const auto hit = cgfs::test::Cast(cast_scene, camera.position, D, 1, 1e9, true);
      if (!hit || cgfs::test::CubeFaceOf(*hit) != face) {
        continue;
      }
      const glm::dvec2 uv = CastUV(scene, cast_scene, *hit);
      const int i = std::clamp(static_cast<int>(std::floor(uv.x * 64)), 0, 63);
      const int j = std::clamp(static_cast<int>(std::floor(uv.y * 64)), 0, 63);
      range = {std::min(range.i_min, i), std::max(range.i_max, i), std::min(range.j_min, j),
               std::max(range.j_max, j)};
    }
  }
  return range;
}

// How many pixels away from the crates' faces' edges show one of the texels that rays
// through points within a pixel and a quarter of theirs hit.
Agreement TexelsAgainstRays(TextureInterpolation interpolation) {
  Model crate = CubeModel();
  crate.texture = &CoordinateTexture();
  Scene scene = SceneCrates(crate);
  scene.lights = {{}};
  scene.lights[0].intensity = 1;  // ambient 1: a pixel is its texel
  Canvas canvas(600, 600);
  RenderScene(scene, canvas, TexturingOf(interpolation, TextureFilter::kNearest));
  const CastScene cast_scene = CastSceneOf(scene);
  const CastCamera camera = CastCameraOf(scene);
  const CastImage cast = CastCameraImage(cast_scene, camera, 600, 600);
  const LabelImage faces = LabelsOf(cast, cgfs::test::CubeFaceOf);
  Agreement agreement;
  for (int y = -300; y < 300; ++y) {
    for (int x = -300; x < 300; ++x) {
      if (faces.At(x, y) < 0 || !faces.Inside(x, y, 2)) {
        continue;
      }
      const TexelRange range = TexelsAround(scene, cast_scene, camera, x, y, faces.At(x, y));
      const cgfs::Rgb8 pixel = canvas.GetPixel(x, y);
      const int i = pixel.r / 4;
      const int j = pixel.g / 4;
      ++agreement.counted;
      agreement.agreeing +=
          range.i_min <= i && i <= range.i_max && range.j_min <= j && j <= range.j_max;
    }
  }
  return agreement;
}

}  // namespace

TEST_CASE("perspective-correct texturing shows the texel a ray through each pixel hits",
          "[texture][ray-cast]") {
  const Agreement correct = TexelsAgainstRays(TextureInterpolation::kPerspectiveCorrect);
  INFO("perspective-correct: " << Describe(correct));
  CHECK(correct.counted > 20000);
  CHECK(correct.Fraction() >= 0.995);
  // Affine texturing is wrong inside the faces, as Figure 14-3 shows.
  const Agreement affine = TexelsAgainstRays(TextureInterpolation::kAffine);
  INFO("affine: " << Describe(affine));
  CHECK(affine.Fraction() < 0.9);
}

namespace {

// A 256 x 256 texture whose every level is one grey, 16 x its level: trilinear
// filtering then blends level L's grey into 16 L, so a pixel says log2 of the texels
// per pixel there.
const MipmappedTexture& LevelTexture() {
  static const MipmappedTexture texture = [] {
    MipmappedTexture levels = BuildMipChain(Texture{256, 256, std::vector<Color>(256 * 256)});
    for (std::size_t k = 0; k < levels.levels.size(); ++k) {
      for (Color& texel : levels.levels[k].texels) {
        texel = Color(16.0 * static_cast<double>(k));
      }
    }
    return levels;
  }();
  return texture;
}

// A floor 4 wide and 37 deep below the camera, the whole texture on it.
Model LevelFloor() {
  Model floor;
  floor.vertices = {{-2, -1, 40}, {2, -1, 40}, {2, -1, 3}, {-2, -1, 3}};
  const std::array<Vec3, 3> up = {Vec3(0, 1, 0), Vec3(0, 1, 0), Vec3(0, 1, 0)};
  Triangle first;
  first.v = {0, 1, 2};
  first.normals = up;
  first.uvs = {glm::dvec2(0, 0), glm::dvec2(1, 0), glm::dvec2(1, 1)};
  Triangle second;
  second.v = {0, 2, 3};
  second.normals = up;
  second.uvs = {glm::dvec2(0, 0), glm::dvec2(1, 1), glm::dvec2(0, 1)};
  floor.triangles = {first, second};
  floor.closed = false;
  floor.texture = &LevelTexture();
  return floor;
}

}  // namespace

TEST_CASE("mipmapping picks the level of the texels a pixel covers, as rays find them",
          "[mipmap][ray-cast]") {
  // The texels per pixel, rho, from the texture coordinates that rays through the pixel
  // and its neighbours to the right and above hit: log2 of the longer step.
  static const Model floor = LevelFloor();
  Scene scene;
  scene.instances = {{&floor, {}}};
  scene.lights = {{}};
  scene.lights[0].intensity = 1;
  Canvas canvas(600, 600);
  RenderScene(scene, canvas,
              TexturingOf(TextureInterpolation::kPerspectiveCorrect, TextureFilter::kTrilinear));
  const CastScene cast_scene = CastSceneOf(scene);
  const CastCamera camera = CastCameraOf(scene);
  const auto uv_at = [&](double x, double y) -> std::optional<glm::dvec2> {
    const glm::dvec3 D(x / 600, y / 600, 1);
    const auto hit = cgfs::test::Cast(cast_scene, camera.position, D, 1, 1e9, true);
    return hit ? std::optional(CastUV(scene, cast_scene, *hit)) : std::nullopt;
  };
  Agreement agreement;
  double worst = 0;
  for (int y = -195; y < -20; y += 2) {
    for (int x = -150; x < 150; x += 3) {
      const auto here = uv_at(x, y);
      const auto right = uv_at(x + 1, y);
      const auto up = uv_at(x, y + 1);
      if (!here || !right || !up) {
        continue;
      }
      const double rho =
          std::max(glm::length(256.0 * (*right - *here)), glm::length(256.0 * (*up - *here)));
      const double level = std::clamp(std::log2(rho), 0.0, 8.0);
      const double drawn = canvas.GetPixel(x, y).r / 16.0;
      ++agreement.counted;
      agreement.agreeing += std::abs(drawn - level) <= 0.15;
      worst = std::max(worst, std::abs(drawn - level));
    }
  }
  INFO(Describe(agreement) << ", worst level difference " << worst);
  CHECK(agreement.counted > 2000);
  CHECK(agreement.Fraction() >= 0.995);
}
