// Listing 10-5's RenderScene, judged by where it draws: chapter 11, which clips what it
// draws, keeps the test (from chapter 12 on, the ray-cast tests judge every pixel).
#include <catch2/catch.hpp>

#include "scenes.h"

TEST_CASE("RenderScene puts instance A's corners where figure 10-10's worked matrices do",
          "[render]") {
  // M = M_camera * M_model (Listing 10-5): vertex 0 lands on (-91, -24) and vertex 6 on
  // (-218, -258), worked out by hand (scene_rendering_test.cpp). M_model * M_camera
  // would move the camera in model space and put them elsewhere.
  Scene scene = SceneTransformedCubes();
  scene.instances.resize(1);
  Canvas canvas(600, 600, cgfs::kWhite);
  RenderScene(scene, canvas);
  const cgfs::Rgb8 white{255, 255, 255};
  CHECK_FALSE(canvas.GetPixel(-91, -24) == white);
  CHECK_FALSE(canvas.GetPixel(-218, -258) == white);
}
