#include "scenes.h"

namespace {

// "Rendering with Diffuse Reflection": the intensities add up to 1.0, so a matte
// scene is never over-exposed.
std::vector<Light> ChapterLights() {
  return {
      {LightType::kAmbient, 0.2, {}, {}},
      {LightType::kPoint, 0.6, {2, 1, 0}, {}},
      {LightType::kDirectional, 0.2, {}, {1, 4, 4}},
  };
}

}  // namespace

// Figure 3-7: the chapter 2 spheres and the huge yellow sphere that looks like a
// floor, all matte (specular -1), so ComputeLighting is diffuse only (Listing 3-1).
Scene SceneDiffuse() {
  Scene scene;
  scene.background_color = cgfs::kWhite;
  scene.spheres = {
      {{0, -1, 3}, 1, cgfs::kRed},
      {{2, 0, 4}, 1, cgfs::kBlue},
      {{-2, 0, 4}, 1, cgfs::kGreen},
      {{0, -5001, 0}, 5000, cgfs::kYellow},
  };
  scene.lights = ChapterLights();
  return scene;
}

// Figure 3-16: the same spheres, now shiny: red 500, blue 500, green 10, yellow 1000.
Scene SceneSpecular() {
  Scene scene = SceneDiffuse();
  scene.spheres = {
      {{0, -1, 3}, 1, cgfs::kRed, 500},
      {{2, 0, 4}, 1, cgfs::kBlue, 500},
      {{-2, 0, 4}, 1, cgfs::kGreen, 10},
      {{0, -5001, 0}, 5000, cgfs::kYellow, 1000},
  };
  return scene;
}

std::vector<cgfs::Figure> Figures() {
  return {
      {"fig-3-7-diffuse", "ambient and diffuse light on matte spheres (Figure 3-7)",
       [](Canvas& canvas) { RenderScene(SceneDiffuse(), canvas); }},
      {"fig-3-16-specular", "diffuse plus specular reflection (Figure 3-16)",
       [](Canvas& canvas) { RenderScene(SceneSpecular(), canvas); }},
  };
}
