#include "scenes.h"

// The scene of "Rendering our First Spheres": three spheres on a white background.
Scene SceneThreeSpheres() {
  Scene scene;
  scene.background_color = cgfs::kWhite;
  scene.spheres = {
      {{0, -1, 3}, 1, cgfs::kRed},
      {{2, 0, 4}, 1, cgfs::kBlue},
      {{-2, 0, 4}, 1, cgfs::kGreen},
  };
  return scene;
}

// The same with the huge yellow sphere that chapter 3 introduces as a floor
// (the author's demo for this chapter already has it).
Scene SceneWithGround() {
  Scene scene = SceneThreeSpheres();
  scene.spheres.push_back({{0, -5001, 0}, 5000, cgfs::kYellow});
  return scene;
}

std::vector<cgfs::Figure> Figures() {
  return {
      {"fig-2-11", "three spheres, flat colours (Figure 2-11)",
       [](Canvas& canvas) { RenderScene(SceneThreeSpheres(), canvas); }},
      {"fig-2-11-with-ground", "the same with the yellow ground sphere (the author's demo)",
       [](Canvas& canvas) { RenderScene(SceneWithGround(), canvas); }},
  };
}
