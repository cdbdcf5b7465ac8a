// The whole card: its pixels, its statistics, its golden image, and its speed-ups.
#include <catch2/catch.hpp>

#include <cmath>

#include <glm/geometric.hpp>

#include "cgfs/canvas.h"
#include "golden.h"
#include "printing.h"
#include "render.h"
#include "scenes.h"

using cgfs::Rgb8;
using cgfs::test::IsSameImageAs;

namespace {

cgfs::Canvas RenderCard(int width, int height, const RenderSettings& settings) {
  cgfs::Canvas canvas(width, height);
  Render(canvas, settings);
  return canvas;
}

}  // namespace

TEST_CASE("RenderPixel: 13 + 224 x the mean sample, whatever the number of samples", "[render]") {
  // The top left pixel, x = 511, y = 511, sees only sky. Its rays leave the eye close to
  // its middle ray, whose sky is 0.7 (1 - d.z)^4 in red.
  const Camera camera = MakeCamera(512, 512);
  const glm::dvec3 middle = glm::normalize(camera.a * 511.5 + camera.b * 511.5 + camera.c);
  const double red = 13 + 224 * 0.7 * std::pow(1 - middle.z, 4);
  RenderSettings settings;
  const glm::ivec3 pixel = RenderPixel(camera, 511, 511, settings);
  CHECK(std::abs(pixel.r - red) <= 2);
  // The same pixel is drawn the same however often, and fewer samples stay close.
  CHECK(RenderPixel(camera, 511, 511, settings) == pixel);
  settings.samples = 4;
  CHECK(std::abs(RenderPixel(camera, 511, 511, settings).r - red) <= 2);
}

TEST_CASE("RenderPixel: the sum is truncated, as the card's (int)p does, not rounded", "[render]") {
  // A camera high above the letters looking level along +x, its image's y collapsed
  // (b = 0): every sample's direction has d.z = 0 exactly, so every sample is the sky
  // at the horizon, (0.7, 0.6, 1.0), and the sum is 13 + 224 (0.7, 0.6, 1.0) =
  // (169.8, 147.4, 237): truncated 169, where rounding gives 170.
  Camera level;
  level.eye = {0, 0, 50};
  level.g = {1, 0, 0};
  level.a = {0, 0.002, 0};
  level.b = {0, 0, 0};
  level.c = {1, -0.512, 0};
  level.aperture = 99;
  CHECK(RenderPixel(level, 100, 200, RenderSettings{}) == glm::ivec3(169, 147, 237));
}

TEST_CASE("business-card matches its golden image and has the original card's statistics",
          "[render][golden]") {
  RenderSettings settings;  // 64 samples, seed 1
  settings.optimizations = AllOptimizations();
  const cgfs::Canvas card = RenderCard(512, 512, settings);

  // The original card, with the C library's rand(), gives a mean of (80.0, 62.2, 75.0),
  // the brightest channel 232 and a white tile (199, 199, 199) at the bottom centre.
  double sum[3] = {0, 0, 0};
  int brightest = 0, darkest = 255;
  for (int y = -256; y < 256; ++y) {
    for (int x = -256; x < 256; ++x) {
      const Rgb8 pixel = card.GetPixel(x, y);
      const int channels[3] = {pixel.r, pixel.g, pixel.b};
      for (int c = 0; c < 3; ++c) {
        sum[c] += channels[c];
        brightest = std::max(brightest, channels[c]);
        darkest = std::min(darkest, channels[c]);
      }
    }
  }
  CHECK(sum[0] / (512 * 512) == Approx(80.0).margin(2));
  CHECK(sum[1] / (512 * 512) == Approx(62.2).margin(2));
  CHECK(sum[2] / (512 * 512) == Approx(75.0).margin(2));
  CHECK(brightest <= 235);
  CHECK(darkest == 13);                         // the base: straight-up sky is black
  const Rgb8 bottom = card.GetPixel(-1, -256);  // the card's x = 256, y = 0
  CHECK(std::abs(bottom.r - 199) <= 2);
  CHECK(bottom.r == bottom.g);
  CHECK(bottom.g == bottom.b);

  cgfs::test::CheckImageAgainstGolden(CGFS_CHAPTER, "business-card", card.GetImage());
}

TEST_CASE("business-card-stratified matches its golden image", "[golden]") {
  cgfs::test::CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "business-card-stratified");
}

namespace {

// Each channel's mean over the image, and its root-mean-square difference from another.
struct Statistics {
  double mean[3] = {0, 0, 0};
  double rms_against = 0;
};

Statistics Measure(const cgfs::Canvas& image, const cgfs::Canvas& reference) {
  Statistics result;
  double squares = 0;
  const int w = image.Width(), h = image.Height();
  for (int y = -h / 2; y < h / 2; ++y) {
    for (int x = -w / 2; x < w / 2; ++x) {
      const Rgb8 a = image.GetPixel(x, y), b = reference.GetPixel(x, y);
      const int channels[3][2] = {{a.r, b.r}, {a.g, b.g}, {a.b, b.b}};
      for (int c = 0; c < 3; ++c) {
        result.mean[c] += channels[c][0];
        squares += (channels[c][0] - channels[c][1]) * (channels[c][0] - channels[c][1]);
      }
    }
  }
  for (double& mean : result.mean) {
    mean /= w * h;
  }
  result.rms_against = std::sqrt(squares / (3.0 * w * h));
  return result;
}

}  // namespace

TEST_CASE("the stratified card: the card's mean, and no more noise than its 64 samples",
          "[render]") {
  // At 128 x 128, against 256 independent samples of another seed: the reference's own
  // noise weighs on both comparisons alike.
  RenderSettings reference_settings;
  reference_settings.samples = 256;
  reference_settings.seed = 99;
  reference_settings.optimizations = AllOptimizations();
  const cgfs::Canvas reference = RenderCard(128, 128, reference_settings);
  RenderSettings card;
  card.optimizations = AllOptimizations();
  RenderSettings stratified = card;
  stratified.samples = kStratifiedSamples;
  stratified.stratified = true;
  const Statistics ours = Measure(RenderCard(128, 128, stratified), reference);
  const Statistics cards = Measure(RenderCard(128, 128, card), reference);
  INFO("rms against the reference: stratified " << ours.rms_against << ", card "
                                                << cards.rms_against);
  CHECK(ours.rms_against <= cards.rms_against);
  for (int c = 0; c < 3; ++c) {
    CHECK(std::abs(ours.mean[c] - cards.mean[c]) <= 1);
  }
  // Independent samples, as few, are noisier: the stratification is what pays.
  RenderSettings few = card;
  few.samples = kStratifiedSamples;
  CHECK(Measure(RenderCard(128, 128, few), reference).rms_against > 1.15 * ours.rms_against);
}

TEST_CASE("business-card-1-sample matches its golden image", "[golden]") {
  cgfs::test::CheckAgainstGolden(CGFS_CHAPTER, Figures({}), "business-card-1-sample");
}

TEST_CASE("threads and the bound leave every pixel as it was", "[render][optimizations]") {
  RenderSettings settings;
  settings.samples = 8;
  const cgfs::Canvas plain = RenderCard(128, 128, settings);
  for (const char* list : {"bound", "threads", "all"}) {
    for (int threads : {2, 7}) {
      INFO(list << ", " << threads << " threads");
      settings.optimizations = OptimizationsNamed({list});
      if (settings.optimizations.threads > 1) {
        settings.optimizations.threads = threads;
      }
      CHECK_THAT(RenderCard(128, 128, settings).GetImage(), IsSameImageAs(plain.GetImage()));
    }
  }
}

TEST_CASE("another seed gives other noise around the same picture", "[render]") {
  RenderSettings settings;
  settings.samples = 8;
  settings.optimizations = AllOptimizations();
  const cgfs::Canvas one = RenderCard(128, 128, settings);
  settings.seed = 2;
  const cgfs::Canvas two = RenderCard(128, 128, settings);
  int changed = 0, far = 0;
  for (int y = -64; y < 64; ++y) {
    for (int x = -64; x < 64; ++x) {
      const int difference = std::abs(one.GetPixel(x, y).r - two.GetPixel(x, y).r);
      changed += difference > 0 ? 1 : 0;
      far += difference > 60 ? 1 : 0;
    }
  }
  CHECK(changed > 128 * 128 / 4);
  CHECK(far < 128 * 128 / 100);
}
