#include "scenes.h"

#include <algorithm>
#include <functional>
#include <memory>
#include <string>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

// "Representing a Cube" (Figure 10-1): vertices A..H are 0..7.
const Model& CubeModel() {
  static const Model cube{
      {
          {1, 1, 1},
          {-1, 1, 1},
          {-1, -1, 1},
          {1, -1, 1},
          {1, 1, -1},
          {-1, 1, -1},
          {-1, -1, -1},
          {1, -1, -1},
      },
      {
          {{0, 1, 2}, cgfs::kRed},
          {{0, 2, 3}, cgfs::kRed},  // z = +1
          {{4, 0, 3}, cgfs::kGreen},
          {{4, 3, 7}, cgfs::kGreen},  // x = +1
          {{5, 4, 7}, cgfs::kBlue},
          {{5, 7, 6}, cgfs::kBlue},  // z = -1
          {{1, 5, 6}, cgfs::kYellow},
          {{1, 6, 2}, cgfs::kYellow},  // x = -1
          {{4, 5, 1}, cgfs::kPurple},
          {{4, 1, 0}, cgfs::kPurple},  // y = +1
          {{2, 6, 7}, cgfs::kCyan},
          {{2, 7, 3}, cgfs::kCyan},  // y = -1
      },
  };
  return cube;
}

// Figure 10-3: two instances of the cube, the camera at the origin.
Scene SceneTwoCubes() {
  Scene scene;
  scene.instances = {
      {&CubeModel(), {1, glm::dmat4(1.0), {-1.5, 0, 7}}},
      {&CubeModel(), {1, glm::dmat4(1.0), {1.25, 2, 7.5}}},
  };
  return scene;
}

// Figure 10-10: the instances scaled and rotated, seen from a camera moved back
// and to the left and turned 30 degrees to the right. Also the scene of
// chapters 11 to 14.
Scene SceneTransformedCubes() {
  Scene scene;
  scene.camera = {{-3, 1, 2}, MakeOYRotationMatrix(-30)};
  scene.instances = {
      {&CubeModel(), {0.75, glm::dmat4(1.0), {-1.5, 0, 7}}},
      {&CubeModel(), {1, MakeOYRotationMatrix(195), {1.25, 2.5, 7.5}}},
  };
  return scene;
}

Scene SceneModel(const Model& model) {
  Vec3 low = model.vertices.front();
  Vec3 high = low;
  for (const Vec3& vertex : model.vertices) {
    low = glm::min(low, vertex);
    high = glm::max(high, vertex);
  }
  const Vec3 centre = (low + high) / 2.0;
  double radius = 0;
  for (const Vec3& vertex : model.vertices) {
    radius = std::max(radius, glm::length(vertex - centre));
  }
  Scene scene;
  scene.instances = {{&model, {1 / radius, glm::dmat4(1.0), Vec3(0, 0, 3) - centre / radius}}};
  return scene;
}

namespace {

// A figure of a scene, drawn by RenderScene, whose camera --window and --view can move.
cgfs::Figure SceneFigure(const std::string& name, const std::string& caption,
                         std::function<Scene()> scene) {
  return {name, caption, [scene](Canvas& canvas) { RenderScene(scene(), canvas); },
          [scene](Canvas& canvas, const cgfs::View& view) {
            Scene moved = scene();
            moved.camera = MovedCamera(moved.camera, view);
            RenderScene(moved, canvas);
          }};
}

// The reader's model, and how many triangles it has.
std::vector<cgfs::Figure> ModelFigures(const ChapterSettings& settings) {
  const std::shared_ptr<const Model> model = settings.model;
  const std::string about =
      settings.model_name + ", " + std::to_string(model->triangles.size()) + " triangles";
  return {SceneFigure("model", about + ", as a wireframe", [model] { return SceneModel(*model); })};
}

}  // namespace

std::vector<cgfs::Figure> Figures(const ChapterSettings& settings) {
  if (settings.model) {
    return ModelFigures(settings);
  }
  return {
      {"fig-10-2", "the cube moved 7 units forward and 1.5 left, RenderObject (Figure 10-2)",
       [](Canvas& canvas) {
         // Listing 10-1 on the cube's vertices, each moved by T = (-1.5, 0, 7).
         std::vector<Vec3> moved = CubeModel().vertices;
         for (Vec3& V : moved) {
           V = V + Vec3(-1.5, 0, 7);
         }
         RenderObject(moved, CubeModel().triangles, canvas, Viewport{});
       }},
      SceneFigure("fig-10-3", "two instances of the cube model (Figure 10-3)", SceneTwoCubes),
      SceneFigure("fig-10-10",
                  "scaled and rotated instances from a moved, turned camera (Figure 10-10)",
                  SceneTransformedCubes),
  };
}
