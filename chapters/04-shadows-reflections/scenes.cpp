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

// Figure 4-4: the shiny spheres of Figure 3-16, now casting shadows.
Scene SceneShadows() {
  Scene scene;
  scene.background_color = cgfs::kWhite;
  scene.spheres = {
      {{0, -1, 3}, 1, cgfs::kRed, 500},
      {{2, 0, 4}, 1, cgfs::kBlue, 500},
      {{-2, 0, 4}, 1, cgfs::kGreen, 10},
      {{0, -5001, 0}, 5000, cgfs::kYellow, 1000},
  };
  scene.lights = ChapterLights();
  return scene;
}

// Figures 4-6 to 4-8: the same spheres, each a little reflective, on black (as in
// the author's reflection demo; black makes the reflections easy to see).
Scene SceneReflections() {
  Scene scene = SceneShadows();
  scene.background_color = cgfs::kBlack;
  scene.spheres = {
      {{0, -1, 3}, 1, cgfs::kRed, 500, 0.2},
      {{2, 0, 4}, 1, cgfs::kBlue, 500, 0.3},
      {{-2, 0, 4}, 1, cgfs::kGreen, 10, 0.4},
      {{0, -5001, 0}, 5000, cgfs::kYellow, 1000, 0.5},
  };
  return scene;
}

// The book's chapter 4 listing moves blue to (-2, 1, 3) and green to (2, 1, 3);
// the author's demos keep them where chapters 2 and 3 had them.
Scene SceneReflectionsBookLayout() {
  Scene scene = SceneReflections();
  scene.spheres[1].center = {-2, 1, 3};
  scene.spheres[2].center = {2, 1, 3};
  return scene;
}

std::vector<cgfs::Figure> Figures() {
  return {
      {"fig-4-4-shadows", "shadows of the point and the directional light (Figure 4-4)",
       [](Canvas& canvas) { RenderScene(SceneShadows(), kDefaultRecursionDepth, canvas); }},
      {"shadow-acne", "the same with shadow rays starting at t = 0: every point shadows itself",
       [](Canvas& canvas) {
         Scene scene = SceneShadows();
         scene.epsilon = 0;
         RenderScene(scene, kDefaultRecursionDepth, canvas);
       }},
      {"fig-4-8-reflections", "reflective spheres, three bounces (Figures 4-7 and 4-8)",
       [](Canvas& canvas) { RenderScene(SceneReflections(), 3, canvas); }},
      {"fig-4-6-recursion-depth-1", "reflections limited to one bounce (Figure 4-6)",
       [](Canvas& canvas) { RenderScene(SceneReflections(), 1, canvas); }},
      {"recursion-depth-0", "no bounce: the reflective scene with local colours only",
       [](Canvas& canvas) { RenderScene(SceneReflections(), 0, canvas); }},
      {"recursion-depth-5", "five bounces, the other depth the web version suggests",
       [](Canvas& canvas) { RenderScene(SceneReflections(), 5, canvas); }},
      {"fig-4-8-reflections-book-layout",
       "three bounces with blue and green where the book's chapter 4 listing puts them",
       [](Canvas& canvas) { RenderScene(SceneReflectionsBookLayout(), 3, canvas); }},
  };
}
