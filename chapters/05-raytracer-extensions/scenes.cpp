#include "scenes.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "cost.h"
#include "csg.h"
#include "meshes.h"
#include "program/cost_view.h"
#include "sampling.h"

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

const Sphere kGround{{0, -5001, 0}, 5000, cgfs::kYellow, 1000, 0.5};
const Color kGrey{160, 160, 160};
const Color kGlass{230, 240, 255};

// A rotation about the X axis by `degrees` (counter-clockwise looking from +X).
glm::dmat3 RotationAboutX(double degrees) {
  const double a = degrees * std::numbers::pi / 180;
  return glm::transpose(glm::dmat3(1, 0, 0,                       //
                                   0, std::cos(a), -std::sin(a),  //
                                   0, std::sin(a), std::cos(a)));
}

std::shared_ptr<Solid> Ball(Vec3 center, double radius, Color color, double specular = 500,
                            double reflective = 0.1, double transparency = 0,
                            double refractive_index = 1) {
  return std::make_shared<Sphere>(center, radius, color, specular, reflective, transparency,
                                  refractive_index);
}

std::shared_ptr<Solid> Csg(CsgOperation operation, std::shared_ptr<Solid> a,
                           std::shared_ptr<Solid> b) {
  return std::make_shared<CsgSolid>(operation, std::move(a), std::move(b));
}

// The book's lens: the common part of two spheres of radius 2 whose centres are
// 3.2 apart along `axis` (unit length), around `center`: 1.2 in radius, 0.8 thick.
std::shared_ptr<Solid> Lens(Vec3 center, Vec3 axis, Color color, double transparency,
                            double refractive_index) {
  return Csg(CsgOperation::kIntersection,
             Ball(center - 1.6 * axis, 2, color, 500, 0.1, transparency, refractive_index),
             Ball(center + 1.6 * axis, 2, color, 500, 0.1, transparency, refractive_index));
}

Scene ChapterSpheresOnBlack() {
  Scene scene;
  scene.background_color = cgfs::kBlack;
  scene.Add(Sphere{{0, -1, 3}, 1, cgfs::kRed, 500, 0.2});
  scene.Add(Sphere{{2, 0, 4}, 1, cgfs::kBlue, 500, 0.3});
  scene.Add(Sphere{{-2, 0, 4}, 1, cgfs::kGreen, 10, 0.4});
  scene.Add(kGround);
  scene.lights = ChapterLights();
  return scene;
}

}  // namespace

// Figures 4-7 and 4-8, as chapter 4 draws them.
Scene SceneReflections() {
  return ChapterSpheresOnBlack();
}

// Figure 5-1, with the author's demo's camera: at (3, 0, 1), turned 45° about the Y
// axis so that it looks towards -X across the spheres. The matrix is written row by
// row as in the book; GLM stores columns, hence the transpose.
Scene SceneCamera() {
  Scene scene = ChapterSpheresOnBlack();
  scene.camera.position = {3, 0, 1};
  scene.camera.rotation = glm::transpose(glm::dmat3(0.7071, 0, -0.7071,  //
                                                    0, 1, 0,             //
                                                    0.7071, 0, 0.7071));
  return scene;
}

Scene SceneSphereField(int count) {
  Scene scene;
  scene.background_color = {200, 220, 255};
  for (Sphere& sphere : SphereField(count, 20261122)) {
    scene.Add(std::move(sphere));
  }
  scene.Add(Sphere{{0, -5001, 0}, 5000, cgfs::kYellow, 1000});
  scene.lights = ChapterLights();
  return scene;
}

Scene SceneTriangles() {
  Scene scene = ChapterSpheresOnBlack();
  // A square pyramid with its apex up behind the spheres, turned so that two faces
  // show. The base corners go round counter-clockwise seen from above, so that each
  // face (corner, apex, next corner) has its normal pointing out.
  const Vec3 apex{0.4, 2, 7};
  const Color colors[4] = {{255, 255, 255}, cgfs::kCyan, cgfs::kPurple, {255, 160, 0}};
  Vec3 base[4];
  for (int k = 0; k < 4; ++k) {
    const double angle = (250.0 + 90 * k) * std::numbers::pi / 180;
    base[k] = {0.4 + 2.1 * std::cos(angle), -1, 7 + 2.1 * std::sin(angle)};
  }
  for (int k = 0; k < 4; ++k) {
    scene.Add(Triangle{base[k], apex, base[(k + 1) % 4], colors[k], 200, 0.3});
  }
  return scene;
}

Scene SceneTorusMesh() {
  Scene scene;
  scene.background_color = {200, 220, 255};
  const glm::dmat3 tilt = RotationAboutX(-55);
  const Vec3 place{0, 0.4, 6};
  for (const Triangle& triangle : TorusMesh(1.6, 0.55, 320, 160, {255, 120, 40})) {
    scene.Add(Triangle{tilt * triangle.A + place, tilt * triangle.B + place,
                       tilt * triangle.C + place, triangle.surface.color,
                       triangle.surface.specular});
  }
  scene.Add(Sphere{{0, -5001, 0}, 5000, {110, 170, 110}, 1000});
  scene.lights = ChapterLights();
  return scene;
}

// A model of the reader's own (--model): scaled and moved so that its bounding sphere
// has radius 1 and its centre 3 units ahead of the camera, on a ground at its lowest
// point, lit by the chapter's lights.
Scene SceneModel(const std::vector<Triangle>& triangles) {
  Vec3 low = triangles.front().A;
  Vec3 high = low;
  for (const Triangle& triangle : triangles) {
    low = glm::min(low, glm::min(triangle.A, glm::min(triangle.B, triangle.C)));
    high = glm::max(high, glm::max(triangle.A, glm::max(triangle.B, triangle.C)));
  }
  const Vec3 centre = (low + high) / 2.0;
  double radius = 0;
  for (const Triangle& triangle : triangles) {
    for (const Vec3& corner : {triangle.A, triangle.B, triangle.C}) {
      radius = std::max(radius, glm::length(corner - centre));
    }
  }
  const auto placed = [&](const Vec3& corner) {
    return (corner - centre) / radius + Vec3(0, 0, 3);
  };
  Scene scene;
  scene.background_color = {200, 220, 255};
  for (const Triangle& triangle : triangles) {
    scene.Add(Triangle{placed(triangle.A), placed(triangle.B), placed(triangle.C),
                       triangle.surface.color, triangle.surface.specular});
  }
  scene.Add(Sphere{{0, (low.y - centre.y) / radius - 5000, 0}, 5000, {110, 170, 110}, 1000});
  scene.lights = ChapterLights();
  return scene;
}

Scene SceneThinWires() {
  Scene scene;
  scene.background_color = {255, 255, 255};
  // At z = 5 a pixel of a 600-pixel canvas is 5/600 units wide.
  const double pixel = 5.0 / 600;
  for (int k = 1; k <= 10; ++k) {
    const double x = -2.2 + 0.44 * (k - 1);
    const double half_width = 0.25 * k * pixel;  // from 0.5 to 5 pixels wide
    const Vec3 a{x - half_width, -2, 5};
    const Vec3 b{x + half_width, -2, 5};
    // Leaning a little, so that each wire crosses columns both traced and skipped.
    const Vec3 c{x + 0.2 + half_width, 2, 5};
    const Vec3 d{x + 0.2 - half_width, 2, 5};
    scene.Add(Triangle{a, d, c, cgfs::kBlack});
    scene.Add(Triangle{a, c, b, cgfs::kBlack});
  }
  scene.lights = {{LightType::kAmbient, 1.0, {}, {}}};
  return scene;
}

Scene SceneCsgOperations() {
  Scene scene;
  scene.background_color = {200, 220, 255};
  const CsgOperation operations[3] = {CsgOperation::kUnion, CsgOperation::kIntersection,
                                      CsgOperation::kDifference};
  for (int i = 0; i < 3; ++i) {
    const Vec3 center{-2.4 + 2.4 * i, 0.2, 7};
    scene.objects.push_back(Csg(operations[i], Ball(center + Vec3(-0.35, 0, 0), 0.8, cgfs::kRed),
                                Ball(center + Vec3(0.35, 0.2, -0.4), 0.7, cgfs::kBlue)));
  }
  scene.Add(Sphere{{0, -5001, 0}, 5000, kGrey, 1000});
  scene.lights = ChapterLights();
  return scene;
}

Scene SceneCsgLens() {
  Scene scene;
  scene.background_color = {200, 220, 255};
  scene.objects.push_back(
      Lens({0, 0.3, 5}, glm::normalize(Vec3{1, 0.3, -1}), {120, 160, 255}, 0, 1));
  scene.Add(Sphere{{0, -5001, 0}, 5000, kGrey, 1000});
  scene.lights = ChapterLights();
  return scene;
}

Scene SceneCsgDeathStar() {
  Scene scene;
  scene.background_color = cgfs::kBlack;
  scene.objects.push_back(Csg(CsgOperation::kDifference, Ball({0, 0.3, 6}, 1.6, kGrey, 50, 0),
                              Ball({-0.9, 0.9, 4.9}, 0.7, {90, 90, 100}, 50, 0)));
  scene.lights = {{LightType::kAmbient, 0.15, {}, {}},
                  {LightType::kPoint, 0.7, {-4, 3, 1}, {}},
                  {LightType::kDirectional, 0.15, {}, {1, 1, -1}}};
  return scene;
}

Scene SceneCsgNested() {
  Scene scene;
  scene.background_color = {200, 220, 255};
  // ((A ∪ B) − C) ∩ D: two spheres joined, a third bitten out of them, and all of it
  // cut down to what lies inside a fourth.
  const auto joined = Csg(CsgOperation::kUnion, Ball({-0.5, 0.3, 6}, 1, cgfs::kRed),
                          Ball({0.5, 0.3, 6}, 1, {255, 160, 0}));
  const auto bitten =
      Csg(CsgOperation::kDifference, joined, Ball({0.2, 1.1, 5.5}, 0.6, cgfs::kBlue));
  scene.objects.push_back(
      Csg(CsgOperation::kIntersection, bitten, Ball({0, 0.3, 6.5}, 1.45, cgfs::kGreen)));
  scene.Add(Sphere{{0, -5001, 0}, 5000, kGrey, 1000});
  scene.lights = ChapterLights();
  return scene;
}

Scene SceneTransparency() {
  Scene scene = ChapterSpheresOnBlack();
  scene.objects[0] = std::make_shared<Sphere>(Vec3{0, -1, 3}, 1, cgfs::kRed, 500, 0.2, 0.6, 1.0);
  return scene;
}

Scene SceneGlassSphere() {
  Scene scene = ChapterSpheresOnBlack();
  scene.background_color = {200, 220, 255};
  scene.Add(Sphere{{0.5, 0.5, 3.5}, 0.6, kGlass, 500, 0.05, 0.9, 1.5});
  return scene;
}

Scene SceneMagnifyingGlass() {
  Scene scene;
  scene.background_color = {200, 220, 255};
  // A wall of letters F at z = 7.5, each of small spheres 0.1 apart: a shape that shows
  // at once whether an image is upright or upside down, mirrored or not.
  constexpr const char* kLetterF[5] = {"###", "#..", "##.", "#..", "#.."};  // top row first
  for (int column = -5; column <= 5; ++column) {
    for (int row = -3; row <= 3; ++row) {
      const double left = 0.45 * column - 0.1;
      const double top = 0.7 * row + 0.2;
      for (int j = 0; j < 5; ++j) {
        for (int i = 0; i < 3; ++i) {
          if (kLetterF[j][i] == '#') {
            scene.Add(Sphere{{left + 0.1 * i, top - 0.1 * j, 7.5}, 0.04, cgfs::kRed, 100});
          }
        }
      }
    }
  }
  // The lens 1.5 in front of the wall, inside its focal length of 2
  // (1/f = (n - 1)(1/R1 + 1/R2) = 0.5 · (1/2 + 1/2)): an upright, magnified image.
  scene.objects.push_back(Lens({0, 0, 6}, {0, 0, 1}, kGlass, 0.95, 1.5));
  scene.lights = {{LightType::kAmbient, 0.4, {}, {}}, {LightType::kPoint, 0.6, {-4, 2, 7.2}, {}}};
  return scene;
}

namespace {

// A figure of a scene, drawn by `render`, whose camera --window and --view can move.
cgfs::Figure SceneFigure(const std::string& name, const std::string& caption,
                         std::function<Scene()> scene,
                         std::function<void(const Scene&, Canvas&)> render) {
  return {name, caption, [scene, render](Canvas& canvas) { render(scene(), canvas); },
          [scene, render](Canvas& canvas, const cgfs::View& view) {
            Scene moved = scene();
            moved.camera = MovedCamera(moved.camera, view);
            render(moved, canvas);
          }};
}

// A cost view: what `count` finds per pixel of a scene, drawn through the cost ramp
// with `scale_max` at its top (program/cost_view.h), its totals said after the caption.
cgfs::Figure CostFigure(const std::string& name, const std::string& caption,
                        std::function<Scene()> make_scene,
                        std::function<std::vector<cgfs::Count>(const Scene&, Canvas&)> count,
                        cgfs::Count scale_max) {
  const cgfs::CostView cost;
  cgfs::Figure figure = SceneFigure(name, caption, std::move(make_scene),
                                    [cost, count, scale_max](const Scene& scene, Canvas& canvas) {
                                      cost.Draw(canvas, count(scene, canvas), scale_max);
                                    });
  figure.measured = cost.Measured();
  return figure;
}

// The box and object tests of each pixel's camera ray, together.
std::function<std::vector<cgfs::Count>(const Scene&, Canvas&)> TestsCounted(
    Optimizations optimizations) {
  return [optimizations](const Scene& scene, Canvas& canvas) {
    TestsPerPixel tests = PrimaryRayTests(scene, canvas, optimizations);
    for (std::size_t i = 0; i < tests.boxes.size(); ++i) {
      tests.objects[i] += tests.boxes[i];
    }
    return tests.objects;
  };
}

// The camera rays a main loop (RenderSceneSubsampled, RenderSceneAdaptive) traces per
// pixel while it draws; the picture it draws is not kept.
template <typename MainLoop>
std::function<std::vector<cgfs::Count>(const Scene&, Canvas&)> CameraRaysCounted(
    MainLoop main_loop, int recursion_depth, Optimizations optimizations) {
  return [main_loop, recursion_depth, optimizations](const Scene& scene, Canvas& canvas) {
    Canvas drawn(canvas.Width(), canvas.Height());
    return CountedPerPixel(kCameraRays, canvas,
                           [&] { main_loop(scene, recursion_depth, drawn, optimizations); });
  };
}

// The rays TraceRay traces per pixel, reflections `depth` deep.
std::function<std::vector<cgfs::Count>(const Scene&, Canvas&)> TracedCounted(
    int depth, Optimizations optimizations) {
  return [depth, optimizations](const Scene& scene, Canvas& canvas) {
    return TracedRays(scene, depth, canvas, optimizations);
  };
}

// The top of the scale of rays traced per pixel, shared by the three views: the most
// any pixel of them takes (the lens's rim).
constexpr cgfs::Count kRaysScale = 25;

// The cost views of the chapter's optimisations, each named after the figure it
// explains.
std::vector<cgfs::Figure> CostFigures(const Optimizations& optimizations) {
  Optimizations loop = optimizations, hierarchy = optimizations;
  loop.bvh = false;
  hierarchy.bvh = true;
  const auto field = [] { return SceneSphereField(10000); };
  return {
      CostFigure("sphere-field-10000-tests",
                 "box and object tests per camera ray through the hierarchy, on a log scale to "
                 "10 001",
                 field, TestsCounted(hierarchy), 10001),
      CostFigure("sphere-field-10000-tests-without-hierarchy",
                 "tests per camera ray without the hierarchy, one per object", field,
                 TestsCounted(loop), 10001),
      CostFigure("subsampling-thin-wires-searches",
                 "the pixels whose camera ray subsampling searched through the scene (white)",
                 SceneThinWires, CameraRaysCounted(RenderSceneSubsampled, 0, optimizations), 1),
      CostFigure("transparency-rays",
                 "rays traced per pixel, the camera's and those reflected and sent through",
                 SceneTransparency, TracedCounted(3, optimizations), kRaysScale),
      CostFigure("refraction-glass-sphere-rays", "rays traced per pixel through the glass ball",
                 SceneGlassSphere, TracedCounted(5, optimizations), kRaysScale),
      CostFigure("refraction-magnifying-glass-rays", "rays traced per pixel through the lens",
                 SceneMagnifyingGlass, TracedCounted(5, optimizations), kRaysScale),
      CostFigure("supersampling-adaptive-rays",
                 "camera rays per pixel of adaptive supersampling, 1 (dark) or 17 (white)",
                 SceneCamera, CameraRaysCounted(RenderSceneAdaptive, 3, optimizations), 17),
  };
}

// The reader's model through the hierarchy, and the box and object tests of each
// pixel's camera ray there.
std::vector<cgfs::Figure> ModelFigures(const ChapterSettings& settings) {
  const std::shared_ptr<const std::vector<Triangle>> model = settings.model;
  const std::string about =
      settings.model_name + ", " + std::to_string(model->size()) + " triangles";
  const std::function<Scene()> scene = [model] { return SceneModel(*model); };
  Optimizations hierarchy = settings.optimizations;
  hierarchy.bvh = true;
  std::vector<cgfs::Figure> figures = {
      SceneFigure("model", about + ", traced", scene,
                  [optimizations = settings.optimizations](const Scene& shown, Canvas& canvas) {
                    RenderSceneAsChosen(shown, 3, canvas, optimizations);
                  }),
      CostFigure("model-tests",
                 about + ": box and object tests per camera ray through the hierarchy, on a "
                         "log scale to 10 001",
                 scene, TestsCounted(hierarchy), 10001),
  };
  cgfs::SetCostView(figures, "model", "model-tests");
  return figures;
}

}  // namespace

std::vector<cgfs::Figure> Figures(const ChapterSettings& settings) {
  if (settings.model) {
    return ModelFigures(settings);
  }
  const Optimizations optimizations = settings.optimizations;
  // The main loop --optimizations chooses, with reflections `depth` deep.
  const auto traced = [optimizations](int depth) {
    return [optimizations, depth](const Scene& scene, Canvas& canvas) {
      RenderSceneAsChosen(scene, depth, canvas, optimizations);
    };
  };
  std::vector<cgfs::Figure> figures = {
      SceneFigure("fig-5-1-camera",
                  "the reflective scene from (3, 0, 1), turned 45 degrees (Figure 5-1)",
                  SceneCamera, traced(3)),
  };
  for (const int count : {100, 1000, 10000, 100000}) {
    figures.push_back(SceneFigure(
        "sphere-field-" + std::to_string(count),
        std::to_string(count) + " small spheres, placed from a fixed seed",
        [count] { return SceneSphereField(count); }, traced(3)));
  }
  const std::vector<cgfs::Figure> more = {
      SceneFigure("triangles", "a mirror pyramid of four triangles behind the spheres",
                  SceneTriangles, traced(3)),
      SceneFigure("torus-mesh", "a torus of 102 400 triangles, through the same hierarchy",
                  SceneTorusMesh, traced(3)),
      SceneFigure("csg-operations", "union, intersection and difference of a red and a blue sphere",
                  SceneCsgOperations, traced(3)),
      SceneFigure("csg-lens", "the book's lens: the intersection of two spheres", SceneCsgLens,
                  traced(3)),
      SceneFigure("csg-death-star", "the book's Death Star: a sphere minus a smaller sphere",
                  SceneCsgDeathStar, traced(3)),
      SceneFigure("csg-nested", "a nested solid, ((A or B) minus C) and D", SceneCsgNested,
                  traced(3)),
      SceneFigure("transparency", "the red sphere 60% see-through, without bending the light",
                  SceneTransparency, traced(3)),
      SceneFigure("refraction-glass-sphere", "a glass sphere (index 1.5) in front of the spheres",
                  SceneGlassSphere, traced(5)),
      SceneFigure("refraction-magnifying-glass",
                  "a glass lens magnifying a wall of letters F, upright", SceneMagnifyingGlass,
                  traced(5)),
      SceneFigure("thin-wires", "wires from half a pixel to five pixels wide, one ray per pixel",
                  SceneThinWires, traced(0)),
      SceneFigure("subsampling-thin-wires",
                  "the same subsampled: the wires under two pixels wide break up", SceneThinWires,
                  [optimizations](const Scene& scene, Canvas& canvas) {
                    RenderSceneSubsampled(scene, 0, canvas, optimizations);
                  }),
  };
  figures.insert(figures.end(), more.begin(), more.end());
  for (const int n : {2, 3, 4}) {  // n = 1 is fig-5-1-camera
    figures.push_back(SceneFigure("supersampling-" + std::to_string(n * n),
                                  "Figure 5-1 with " + std::to_string(n * n) + " rays per pixel",
                                  SceneCamera,
                                  [n, optimizations](const Scene& scene, Canvas& canvas) {
                                    RenderSceneSupersampled(scene, 3, n, canvas, optimizations);
                                  }));
  }
  figures.push_back(SceneFigure("supersampling-adaptive",
                                "Figure 5-1 with 16 rays only where neighbours differ", SceneCamera,
                                [optimizations](const Scene& scene, Canvas& canvas) {
                                  RenderSceneAdaptive(scene, 3, canvas, optimizations);
                                }));
  const std::vector<cgfs::Figure> costs = CostFigures(optimizations);
  figures.insert(figures.end(), costs.begin(), costs.end());
  cgfs::SetCostView(figures, "sphere-field-10000", "sphere-field-10000-tests");
  cgfs::SetCostView(figures, "subsampling-thin-wires", "subsampling-thin-wires-searches");
  cgfs::SetCostView(figures, "supersampling-adaptive", "supersampling-adaptive-rays");
  for (const char* name :
       {"transparency", "refraction-glass-sphere", "refraction-magnifying-glass"}) {
    cgfs::SetCostView(figures, name, std::string(name) + "-rays");
  }
  return figures;
}
