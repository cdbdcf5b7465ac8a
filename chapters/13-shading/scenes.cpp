#include "scenes.h"

#include <algorithm>
#include <functional>
#include <memory>
#include <string>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "sphere_model.h"

// "Representing a Cube" (Figure 10-1): vertices A..H are 0..7. "Normals": each face's
// two triangles have its normal at every corner.
const Model& CubeModel() {
  const auto face = [](const Vec3& N) { return std::array<Vec3, 3>{N, N, N}; };
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
          {{0, 1, 2}, cgfs::kRed, face({0, 0, 1})},
          {{0, 2, 3}, cgfs::kRed, face({0, 0, 1})},  // z = +1
          {{4, 0, 3}, cgfs::kGreen, face({1, 0, 0})},
          {{4, 3, 7}, cgfs::kGreen, face({1, 0, 0})},  // x = +1
          {{5, 4, 7}, cgfs::kBlue, face({0, 0, -1})},
          {{5, 7, 6}, cgfs::kBlue, face({0, 0, -1})},  // z = -1
          {{1, 5, 6}, cgfs::kYellow, face({-1, 0, 0})},
          {{1, 6, 2}, cgfs::kYellow, face({-1, 0, 0})},  // x = -1
          {{4, 5, 1}, cgfs::kPurple, face({0, 1, 0})},
          {{4, 1, 0}, cgfs::kPurple, face({0, 1, 0})},  // y = +1
          {{2, 6, 7}, cgfs::kCyan, face({0, -1, 0})},
          {{2, 7, 3}, cgfs::kCyan, face({0, -1, 0})},  // y = -1
      },
  };
  return cube;
}

// Figure 10-10: the instances scaled and rotated, seen from a camera moved back
// and to the left and turned 30 degrees to the right.
Scene SceneTransformedCubes() {
  Scene scene;
  scene.camera = {{-3, 1, 2}, MakeOYRotationMatrix(-30)};
  scene.instances = {
      {&CubeModel(), {0.75, glm::dmat4(1.0), {-1.5, 0, 7}}},
      {&CubeModel(), {1, MakeOYRotationMatrix(195), {1.25, 2.5, 7.5}}},
  };
  return scene;
}

// The lights of Figures 13-1 to 13-9, in world space.
std::vector<Light> ShadingLights() {
  return {
      {LightType::kAmbient, 0.2},
      {LightType::kDirectional, 0.2, {}, {-1, 0, 1}},
      {LightType::kPoint, 0.6, {-3, 2, -10}},
  };
}

// Figure 10-10's scene and a green sphere of 15 divisions, scale 1.5, lower right.
Scene SceneShading() {
  static const Model sphere = GenerateSphere(15, cgfs::kGreen);
  Scene scene = SceneTransformedCubes();
  scene.instances.push_back({&sphere, {1.5, glm::dmat4(1.0), {1.75, -0.5, 7}}});
  scene.lights = ShadingLights();
  return scene;
}

// The cube's green face alone (triangles 4, 0, 3 and 4, 3, 7; an open model), turned
// 30 degrees towards the camera at (-2, 0, 5); a point light 0.6 at (2.25, 0, 5),
// marked by a small yellow sphere; ambient 0.2.
Scene SceneCloseLight() {
  static const Model face = [] {
    Model model;
    model.vertices = CubeModel().vertices;
    model.triangles = {CubeModel().triangles[2], CubeModel().triangles[3]};
    model.closed = false;
    return model;
  }();
  static const Model marker = GenerateSphere(15, cgfs::kYellow);
  const Vec3 light_position(2.25, 0, 5);
  Scene scene;
  scene.instances = {
      {&face, {1, MakeOYRotationMatrix(-30), {-2, 0, 5}}},
      {&marker, {0.1, glm::dmat4(1.0), light_position}},
  };
  scene.lights = {{LightType::kAmbient, 0.2}, {LightType::kPoint, 0.6, light_position}};
  return scene;
}

// Chapter 4's spheres (red, blue, green; the yellow ground sphere of radius 5000
// becomes a floor at y = -1) and chapter 3's lights, with the camera at the origin.
Scene SceneRaytracerSpheres() {
  static const Model red = [] {
    Model model = GenerateSphere(15, cgfs::kRed);
    model.specular = 500;
    return model;
  }();
  static const Model blue = [] {
    Model model = GenerateSphere(15, cgfs::kBlue);
    model.specular = 500;
    return model;
  }();
  static const Model green = [] {
    Model model = GenerateSphere(15, cgfs::kGreen);
    model.specular = 10;
    return model;
  }();
  // A square 100 units wide at y = 0, wound to face up; clipping cuts away what is
  // behind the camera or outside the view.
  static const Model floor{
      {{-50, 0, -50}, {-50, 0, 50}, {50, 0, 50}, {50, 0, -50}},
      {{{0, 1, 2}, cgfs::kYellow, {Vec3(0, 1, 0), Vec3(0, 1, 0), Vec3(0, 1, 0)}},
       {{0, 2, 3}, cgfs::kYellow, {Vec3(0, 1, 0), Vec3(0, 1, 0), Vec3(0, 1, 0)}}},
      false,
  };
  Scene scene;
  scene.instances = {
      {&red, {1, glm::dmat4(1.0), {0, -1, 3}}},
      {&blue, {1, glm::dmat4(1.0), {2, 0, 4}}},
      {&green, {1, glm::dmat4(1.0), {-2, 0, 4}}},
      {&floor, {1, glm::dmat4(1.0), {0, -1, 0}}},
  };
  scene.lights = {
      {LightType::kAmbient, 0.2},
      {LightType::kPoint, 0.6, {2, 1, 0}},
      {LightType::kDirectional, 0.2, {}, {1, 4, 4}},
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
  scene.lights = ShadingLights();
  scene.instances = {{&model, {1 / radius, glm::dmat4(1.0), Vec3(0, 0, 3) - centre / radius}}};
  return scene;
}

namespace {

// The systematic name of a shading: e.g. "phong-model-normals-diffuse-specular".
std::string NameOf(const Shading& shading) {
  const char* model = shading.model == ShadingModel::kFlat      ? "flat"
                      : shading.model == ShadingModel::kGouraud ? "gouraud"
                                                                : "phong";
  const char* normals =
      shading.normals == NormalSource::kTriangle ? "triangle-normals" : "model-normals";
  const char* terms = !shading.terms.specular  ? "diffuse"
                      : !shading.terms.diffuse ? "specular"
                                               : "diffuse-specular";
  return std::string(model) + "-" + normals + "-" + terms;
}

// The book's figures of the base scene, by the shading they use.
std::string BookFigureNumber(const Shading& shading) {
  if (!shading.terms.diffuse || !shading.terms.specular) {
    return "";
  }
  const bool triangle_normals = shading.normals == NormalSource::kTriangle;
  switch (shading.model) {
    case ShadingModel::kFlat:
      return triangle_normals ? "fig-13-1-" : "";
    case ShadingModel::kGouraud:
      return triangle_normals ? "fig-13-3-" : "fig-13-6-";
    case ShadingModel::kPhong:
      return triangle_normals ? "" : "fig-13-9-";
  }
  return "";
}

// A figure of a scene, drawn by RenderScene with `shading`, whose camera --window and
// --view can move.
cgfs::Figure SceneFigure(const std::string& name, const std::string& caption,
                         std::function<Scene()> scene, const Shading& shading) {
  return {name, caption,
          [scene, shading](Canvas& canvas) { RenderScene(scene(), canvas, shading); },
          [scene, shading](Canvas& canvas, const cgfs::View& view) {
            Scene moved = scene();
            moved.camera = MovedCamera(moved.camera, view);
            RenderScene(moved, canvas, shading);
          }};
}

// The reader's model flat-shaded with its triangles' normals, and Phong-shaded with
// the model's.
std::vector<cgfs::Figure> ModelFigures(const ChapterSettings& settings) {
  const std::shared_ptr<const Model> model = settings.model;
  const std::string about = settings.model_name + ", " + std::to_string(model->triangles.size()) +
                            " triangles, " +
                            (model->closed ? "closed: back faces culled" : "not closed");
  const std::function<Scene()> scene = [model] { return SceneModel(*model); };
  return {SceneFigure("model-flat", about + ", flat shading with the triangles' normals", scene,
                      {ShadingModel::kFlat, NormalSource::kTriangle, {}}),
          SceneFigure("model", about + ", Phong shading with the model's normals", scene, {})};
}

}  // namespace

std::vector<cgfs::Figure> Figures(const ChapterSettings& settings) {
  if (settings.model) {
    return ModelFigures(settings);
  }
  std::vector<cgfs::Figure> figures;
  // The base scene in every combination: shading model x normals x lighting terms.
  for (const ShadingModel model :
       {ShadingModel::kFlat, ShadingModel::kGouraud, ShadingModel::kPhong}) {
    for (const NormalSource normals : {NormalSource::kTriangle, NormalSource::kModel}) {
      for (const LightingTerms terms :
           {LightingTerms{true, false}, LightingTerms{false, true}, LightingTerms{true, true}}) {
        const Shading shading{model, normals, terms};
        figures.push_back(SceneFigure(BookFigureNumber(shading) + NameOf(shading),
                                      "the cubes and the sphere, " + NameOf(shading), SceneShading,
                                      shading));
      }
    }
  }
  figures.push_back(
      SceneFigure("fig-13-7-close-light-gouraud",
                  "a large face lit from close by, Gouraud: the corners are dim, so all is",
                  SceneCloseLight, {ShadingModel::kGouraud, NormalSource::kModel, {}}));
  figures.push_back(SceneFigure("fig-13-10-close-light-phong",
                                "the same face, Phong: the bright spot nearest the light",
                                SceneCloseLight, {}));
  figures.push_back(SceneFigure("fig-13-11-raytracer-spheres",
                                "the ray tracer's spheres and lights rasterized, Phong shading",
                                SceneRaytracerSpheres, {}));
  return figures;
}
