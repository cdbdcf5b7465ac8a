// Chapter 15, "Stencil Shadows", step 1: multi-pass lighting.
#include <catch2/catch.hpp>

#include "comparison/compare.h"
#include "multipass_lighting.h"
#include "scenes.h"

TEST_CASE("the accumulation buffer adds each pass once per pixel, and clamps at the end",
          "[multipass]") {
  Canvas canvas(4, 4, cgfs::kBlack);
  AccumulationBuffer sum(canvas);
  sum.Set(0, 0, {100, 50, 0});
  sum.Set(0, 0, {200, 150, 10});  // a closer triangle replaces the farther one
  sum.BeginPass();
  CHECK(sum.Add(0, 0, {100, 50, 20}));
  CHECK_FALSE(sum.Add(0, 0, {100, 50, 20}));  // a second triangle on the same pixel
  CHECK_FALSE(sum.CanAdd(0, 0));
  CHECK_FALSE(sum.Add(7, 7, {1, 1, 1}));  // off the canvas
  sum.BeginPass();
  CHECK(sum.Add(0, 0, {0, 0, 0.4}));
  sum.WriteTo(canvas);
  CHECK(canvas.GetPixel(0, 0) == cgfs::Rgb8{255, 200, 30});
  CHECK(canvas.GetPixel(1, 1) == cgfs::Rgb8{0, 0, 0});  // no pass drew it: left alone
}

TEST_CASE("the passes of chapter 13's scene add up to the one-pass image", "[multipass]") {
  // Clamped once after a floating-point sum, passes differ from one pass only where
  // the sums round differently: by one level at most.
  Canvas one_pass(600, 600);
  RenderScene(SceneShading(), one_pass);
  Canvas passes(600, 600);
  Extensions extensions;
  extensions.multipass_lighting = true;
  RenderScene(SceneShading(), passes, {}, extensions);
  const cgfs::Comparison comparison = cgfs::CompareImages(one_pass.GetImage(), passes.GetImage());
  CHECK(comparison.max_channel_difference <= 1);
  CHECK(comparison.changed_pixels < 600 * 600 / 100);
}

TEST_CASE("in passes, the reflection is added once, as the ambient light is", "[multipass]") {
  // The mirror sphere reflects its cube map in the first pass only: added in every
  // pass, the reflection would count once per light.
  const Model crate = TexturedCube(*CrateTexture({}));
  Extensions one_pass;
  one_pass.environment_mapping = true;
  Extensions in_passes = one_pass;
  in_passes.multipass_lighting = true;
  Canvas expected(600, 600);
  RenderScene(SceneMirrorSphere(crate), expected, {}, one_pass);
  Canvas drawn(600, 600);
  RenderScene(SceneMirrorSphere(crate), drawn, {}, in_passes);
  const cgfs::Comparison comparison = cgfs::CompareImages(expected.GetImage(), drawn.GetImage());
  CHECK(comparison.max_channel_difference <= 1);
}
