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

// The scene of Figure 10-10 and a third cube, behind the camera: its bounding
// sphere lies wholly behind the near plane, so the whole cube is rejected.
Scene SceneWithCubeBehindCamera() {
  Scene scene = SceneTransformedCubes();
  scene.instances.push_back({&CubeModel(), {1, MakeOYRotationMatrix(195), {0, 0, -10}}});
  return scene;
}

// A small cube, turned 30 degrees, whose middle lies on the near plane z = 1: the
// plane cuts it in two, and the triangles that cross it are split. The part in
// front of the plane is drawn; the new edges along the cut show where it was.
Scene SceneCubeCutByNearPlane() {
  Scene scene;
  scene.instances = {
      {&CubeModel(), {0.25, MakeOYRotationMatrix(30), {0.05, -0.1, 1.05}}},
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
      SceneFigure(
          "clipped-scene",
          "the scene of Figure 10-10 with a third cube behind the camera, which clipping rejects",
          SceneWithCubeBehindCamera),
      SceneFigure("near-plane-cut", "a cube cut by the near plane: its triangles there are split",
                  SceneCubeCutByNearPlane),
  };
}
