#include "scenes.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "normal_mapping.h"
#include "program/cost_view.h"
#include "sphere_model.h"

// "Representing a Cube" (Figure 10-1): vertices A..H are 0..7. "Normals": each face's
// two triangles have its normal at every corner. "Painting a Crate": each face's first
// triangle (A, B, C) has (u, v) = (0, 0), (1, 0), (1, 1), its second (A, C, D) has
// (0, 0), (1, 1), (0, 1): the whole texture on every face.
const Model& CubeModel() {
  const auto face = [](const Vec3& N) { return std::array<Vec3, 3>{N, N, N}; };
  const std::array<glm::dvec2, 3> first = {glm::dvec2(0, 0), glm::dvec2(1, 0), glm::dvec2(1, 1)};
  const std::array<glm::dvec2, 3> second = {glm::dvec2(0, 0), glm::dvec2(1, 1), glm::dvec2(0, 1)};
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
          {{0, 1, 2}, cgfs::kRed, face({0, 0, 1}), first},
          {{0, 2, 3}, cgfs::kRed, face({0, 0, 1}), second},  // z = +1
          {{4, 0, 3}, cgfs::kGreen, face({1, 0, 0}), first},
          {{4, 3, 7}, cgfs::kGreen, face({1, 0, 0}), second},  // x = +1
          {{5, 4, 7}, cgfs::kBlue, face({0, 0, -1}), first},
          {{5, 7, 6}, cgfs::kBlue, face({0, 0, -1}), second},  // z = -1
          {{1, 5, 6}, cgfs::kYellow, face({-1, 0, 0}), first},
          {{1, 6, 2}, cgfs::kYellow, face({-1, 0, 0}), second},  // x = -1
          {{4, 5, 1}, cgfs::kPurple, face({0, 1, 0}), first},
          {{4, 1, 0}, cgfs::kPurple, face({0, 1, 0}), second},  // y = +1
          {{2, 6, 7}, cgfs::kCyan, face({0, -1, 0}), first},
          {{2, 7, 3}, cgfs::kCyan, face({0, -1, 0}), second},  // y = -1
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

std::shared_ptr<const MipmappedTexture> CrateTexture(const ChapterSettings& settings) {
  static const auto ours =
      std::make_shared<const MipmappedTexture>(BuildMipChain(MakeCrateTexture(256)));
  return settings.crate_texture ? settings.crate_texture : ours;
}

Model TexturedCube(const MipmappedTexture& texture) {
  Model model = CubeModel();
  model.texture = &texture;
  return model;
}

// Figures 14-3 and 14-5: three crates, seen from Figure 10-10's camera, lit as in
// chapter 13.
Scene SceneCrates(const Model& crate) {
  Scene scene;
  scene.camera = {{-3, 1, 2}, MakeOYRotationMatrix(-30)};
  scene.instances = {
      {&crate, {0.75, glm::dmat4(1.0), {-1.5, 0, 7}}},
      {&crate, {1, MakeOYRotationMatrix(195), {1.25, 2.5, 7.5}}},
      {&crate, {1, MakeOYRotationMatrix(-30), {1.75, 0, 5}}},
  };
  scene.lights = ShadingLights();
  return scene;
}

namespace {

// A flat quad with corners a (top-left), b, c, d in order around it, (b - a) x (c - a)
// its outward normal; the whole texture on it, (u, v) = (0, 0) at a. Open: it has
// one side.
Model Quad(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Color& color) {
  const Vec3 N = ComputeTriangleNormal(a, b, c);
  const std::array<Vec3, 3> normals = {N, N, N};
  Model model;
  model.vertices = {a, b, c, d};
  model.triangles = {
      {{0, 1, 2}, color, normals, {glm::dvec2(0, 0), glm::dvec2(1, 0), glm::dvec2(1, 1)}},
      {{0, 2, 3}, color, normals, {glm::dvec2(0, 0), glm::dvec2(1, 1), glm::dvec2(0, 1)}}};
  model.closed = false;
  return model;
}

// A floor 20 x 20 at height y, from z = -2 to z = 18.
Model Floor(double y) {
  return Quad({-10, y, 18}, {10, y, 18}, {10, y, -2}, {-10, y, -2}, Color(200, 200, 200));
}

const MipmappedTexture& FloorCheckerboard() {
  static const MipmappedTexture checkerboard =
      BuildMipChain(MakeCheckerboard(512, 16, Color(200, 60, 50), Color(235, 235, 235)));
  return checkerboard;
}

}  // namespace

// Each bump is a pyramid over its cell, h = k (1 - |x| - |y|) with x and y in [-1, 1]
// across the cell; the normal of a height field h(u, v) in tangent space is
// (-dh/du, -dh/dv, 1), normalised, here (k sign(x), k sign(y), 1) on the four faces.
// The corners between the bumps are flat. Encoded as c = 255 (n + 1) / 2, rounded.
Texture MakeDiamondNormalMap(int size, int bumps) {
  Texture texture{size, size, {}};
  const double cell = static_cast<double>(size) / bumps;
  for (int j = 0; j < size; ++j) {
    for (int i = 0; i < size; ++i) {
      const double x = std::fmod(i + 0.5, cell) / cell * 2 - 1;
      const double y = std::fmod(j + 0.5, cell) / cell * 2 - 1;
      Vec3 n(0, 0, 1);
      if (std::abs(x) + std::abs(y) < 1) {
        const double k = 0.75;  // the faces lean 47 degrees from the surface
        n = glm::normalize(Vec3(x > 0 ? k : -k, y > 0 ? k : -k, 1));
      }
      texture.texels.push_back(glm::round(255.0 * (n + 1.0) / 2.0));
    }
  }
  return texture;
}

Texture MakeDiamondTiles(int size, int bumps) {
  Texture texture{size, size, {}};
  const double cell = static_cast<double>(size) / bumps;
  const Color stone(214, 192, 152);
  const Color grout(104, 88, 72);
  for (int j = 0; j < size; ++j) {
    for (int i = 0; i < size; ++i) {
      const double x = std::fmod(i + 0.5, cell) / cell * 2 - 1;
      const double y = std::fmod(j + 0.5, cell) / cell * 2 - 1;
      const bool on_a_bump = std::abs(x) + std::abs(y) < 1;
      const bool lighter =
          (static_cast<int>((i + 0.5) / cell) + static_cast<int>((j + 0.5) / cell)) % 2 == 0;
      texture.texels.push_back(on_a_bump ? stone * (lighter ? 1.0 : 0.88) : grout);
    }
  }
  return texture;
}

const Texture& DiamondNormalMap() {
  static const Texture normal_map = MakeDiamondNormalMap(256, 8);
  return normal_map;
}

const MipmappedTexture& DiamondTiles() {
  static const MipmappedTexture tiles = BuildMipChain(MakeDiamondTiles(256, 8));
  return tiles;
}

Scene SceneNormalMappedSquare(bool light_from_left) {
  static const Model square = [] {
    Model model = Quad({-1, 1, 5}, {1, 1, 5}, {1, -1, 5}, {-1, -1, 5}, cgfs::kWhite);
    model.texture = &DiamondTiles();
    model.normal_map = &DiamondNormalMap();
    return model;
  }();
  Scene scene;
  scene.instances = {{&square, {}}};
  scene.lights = {{LightType::kAmbient, 0.2},
                  {LightType::kPoint, 0.8, {light_from_left ? -3.0 : 3.0, 0, 4}}};
  return scene;
}

Scene SceneMirrorSphere(const Model& crate) {
  static const Model floor = [] {
    Model model = Floor(-1);
    model.texture = &FloorCheckerboard();
    return model;
  }();
  static const Model mirror = [] {
    Model model = GenerateSphere(24, Color(40, 40, 40));
    model.specular = 500;
    model.reflective = 0.8;
    return model;
  }();
  Scene scene = SceneCrates(crate);
  scene.instances.push_back({&floor, {}});
  scene.instances.push_back({&mirror, {1, glm::dmat4(1.0), {0.6, 0, 7.2}}});
  scene.lights = {{LightType::kAmbient, 0.25}, {LightType::kPoint, 0.75, {-4, 7, 4}}};
  return scene;
}

Scene SceneShading() {
  static const Model sphere = GenerateSphere(15, cgfs::kGreen);
  Scene scene = SceneTransformedCubes();
  scene.instances.push_back({&sphere, {1.5, glm::dmat4(1.0), {1.75, -0.5, 7}}});
  scene.lights = ShadingLights();
  return scene;
}

Scene SceneShadows() {
  static const Model floor = Floor(-2);
  Scene scene = SceneShading();
  scene.instances.push_back({&floor, {}});
  scene.lights = {{LightType::kAmbient, 0.2}, {LightType::kPoint, 0.8, {-4, 7, 4}}};
  return scene;
}

Scene SceneShadowsDirectional() {
  Scene scene = SceneShadows();
  scene.lights = {{LightType::kAmbient, 0.2}, {LightType::kDirectional, 0.8, {}, {-1, 2, -0.5}}};
  return scene;
}

Scene SceneCameraInShadow() {
  static const Model floor = Floor(0);
  static const Model sphere = GenerateSphere(15, cgfs::kGreen);
  Scene scene;
  scene.camera = {{0, 1, 0}, glm::dmat4(1.0)};
  scene.instances = {
      {&CubeModel(), {1.5, glm::dmat4(1.0), {0, 4, 2}}},  // the slab overhead, out of view
      {&sphere, {0.8, glm::dmat4(1.0), {-1, 0.8, 6}}},
      {&CubeModel(), {0.6, MakeOYRotationMatrix(30), {1.2, 0.6, 5}}},
      {&floor, {}},
  };
  scene.lights = {{LightType::kAmbient, 0.2}, {LightType::kPoint, 0.8, {0, 10, 6}}};
  return scene;
}

Scene SceneCubeOverFloor() {
  static const Model floor = Floor(-1);
  Scene scene;
  // Two units up, looking 25 degrees down: a turn about X, as MakeOYRotationMatrix
  // turns about Y.
  scene.camera = {{0, 2, 1}, glm::rotate(glm::dmat4(1.0), glm::radians(25.0), Vec3(1, 0, 0))};
  scene.instances = {
      {&CubeModel(), {0.7, MakeOYRotationMatrix(30), {-0.5, 0, 6}}},
      {&floor, {}},
  };
  scene.lights = {{LightType::kAmbient, 0.2}, {LightType::kPoint, 0.8, {-3.5, 3.5, 4.5}}};
  return scene;
}

Scene SceneEverything(const Model& crate) {
  static const Model floor = [] {
    Model model = Floor(-1);
    model.texture = &FloorCheckerboard();
    model.normal_map = &DiamondNormalMap();
    return model;
  }();
  Scene scene = SceneMirrorSphere(crate);
  scene.instances[3].model = &floor;
  return scene;
}

// Chapter 14's, on a floor at the model's lowest point, lit from above and to the left
// of the camera so that its shadow falls on the floor behind it.
Scene SceneModel(const std::vector<Model>& parts) {
  static const Model floor = Floor(0);
  // The box and sphere around every part's vertices (each part has those it uses).
  Vec3 low = parts.front().vertices.front();
  Vec3 high = low;
  for (const Model& part : parts) {
    for (const Vec3& vertex : part.vertices) {
      low = glm::min(low, vertex);
      high = glm::max(high, vertex);
    }
  }
  const Vec3 centre = (low + high) / 2.0;
  double radius = 0;
  for (const Model& part : parts) {
    for (const Vec3& vertex : part.vertices) {
      radius = std::max(radius, glm::length(vertex - centre));
    }
  }
  Scene scene;
  scene.lights = {{LightType::kAmbient, 0.2}, {LightType::kPoint, 0.8, {-3, 4, 0}}};
  const Transform placed{1 / radius, glm::dmat4(1.0), Vec3(0, 0, 3) - centre / radius};
  for (const Model& part : parts) {
    scene.instances.push_back({&part, placed});
  }
  scene.instances.push_back({&floor, {1, glm::dmat4(1.0), {0, (low.y - centre.y) / radius, 0}}});
  return scene;
}

namespace {

// "Environment Mapping": a cube map unfolded as a cross, each face `size` pixels
// wide: +Y above +Z, then -X, +Z, +X, -Z in a row, -Y below +Z.
void DrawCubeMap(const CubeMap& cube_map, Canvas& canvas) {
  const int size = cube_map.faces[0].width;
  const auto draw = [&](CubeFace face, int column, int row) {
    const Texture& texture = cube_map.faces[static_cast<std::size_t>(face)];
    for (int j = 0; j < size; ++j) {
      for (int i = 0; i < size; ++i) {
        const cgfs::CanvasPoint point = canvas.ToCanvas(column * size + i, row * size + j);
        canvas.PutPixel(point.x, point.y, texture.At(i, j));
      }
    }
  };
  draw(CubeFace::kPositiveY, 1, 0);
  draw(CubeFace::kNegativeX, 0, 1);
  draw(CubeFace::kPositiveZ, 1, 1);
  draw(CubeFace::kPositiveX, 2, 1);
  draw(CubeFace::kNegativeZ, 3, 1);
  draw(CubeFace::kNegativeY, 1, 2);
}

// Figure 15-2: a normal map shown as the RGB texture it is, filling the canvas.
void DrawTexture(const Texture& texture, Canvas& canvas) {
  for (int row = 0; row < canvas.Height(); ++row) {
    for (int column = 0; column < canvas.Width(); ++column) {
      const cgfs::CanvasPoint point = canvas.ToCanvas(column, row);
      canvas.PutPixel(point.x, point.y,
                      GetTexelNearest(texture, (column + 0.5) * texture.width / canvas.Width(),
                                      (row + 0.5) * texture.height / canvas.Height()));
    }
  }
}

// Figure 15-4: the edges of the occluder's shadow volume as `light` casts it, from the
// silhouette down to where they meet the floor at y = floor_y, drawn over the canvas
// in dark red: the outline they trace on the floor is the shadow's.
void DrawShadowVolumeEdges(const Scene& scene, const Instance& occluder, const Light& light,
                           double floor_y, Canvas& canvas) {
  Model world = *occluder.model;
  for (Vec3& V : world.vertices) {
    V = ApplyTransform(V, occluder.transform);
  }
  const glm::dmat4 M_camera = MakeCameraMatrix(scene.camera.position, scene.camera.orientation);
  const auto project = [&](const Vec3& V) {
    return ProjectVertex(cgfs::ToCartesian(M_camera * glm::dvec4(V, 1.0)), canvas, scene.viewport);
  };
  const auto on_floor = [&](const Vec3& V) {
    const Vec3 away = V - light.position;
    return V + away * ((floor_y - V.y) / away.y);
  };
  const Color edge(150, 0, 0);
  for (const auto& [a, b] : SilhouetteEdges(world, light)) {
    const Vec3& A = world.vertices[static_cast<std::size_t>(a)];
    const Vec3& B = world.vertices[static_cast<std::size_t>(b)];
    DrawLine(project(A), project(B), edge, canvas);
    DrawLine(project(A), project(on_floor(A)), edge, canvas);
    DrawLine(project(on_floor(A)), project(on_floor(B)), edge, canvas);
  }
}

template <typename Change>
Extensions With(const Change& change) {
  Extensions extensions;
  change(extensions);
  return extensions;
}

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

// The same, drawn by RenderScene with `extensions`.
cgfs::Figure SceneFigure(const std::string& name, const std::string& caption,
                         std::function<Scene()> scene, const Extensions& extensions) {
  return SceneFigure(name, caption, std::move(scene),
                     [extensions](const Scene& shown, Canvas& canvas) {
                       RenderScene(shown, canvas, {}, extensions);
                     });
}

}  // namespace

namespace {

// "Normal Mapping": Figures 15-1 and 15-2.
std::vector<cgfs::Figure> NormalMapFigures() {
  const auto square = [](bool light_from_left) {
    return [light_from_left] { return SceneNormalMappedSquare(light_from_left); };
  };
  const Extensions mapped = With([](Extensions& e) { e.normal_mapping = true; });
  return {
      SceneFigure("fig-15-1a-textured-square", "a square of stone tiles lit from the left: flat",
                  square(true), Extensions{}),
      SceneFigure("fig-15-1b-normal-map-lit-from-left",
                  "the same square with a normal map: diamond bumps, lit on their left faces",
                  square(true), mapped),
      SceneFigure("fig-15-1c-normal-map-lit-from-right",
                  "the same, lit from the right: the other faces", square(false), mapped),
      {"fig-15-2-normal-map", "the normal map of figure 15-1 as an RGB texture: blue-purple",
       [](Canvas& canvas) { DrawTexture(DiamondNormalMap(), canvas); }},
  };
}

// The tops of the scales of the shadows' cost views: the most any pixel of them takes.
constexpr cgfs::Count kStencilWritesScale = 20;
constexpr cgfs::Count kPixelsPerEntryScale = 404;

// What `counter` tallies per pixel (from `initial`) while the scene is drawn with
// `extensions` (cgfs/tally.h).
std::vector<cgfs::Count> CountedWhileDrawing(const cgfs::Counter& counter, cgfs::Count initial,
                                             const Scene& scene, Canvas& canvas,
                                             const Extensions& extensions) {
  const cgfs::Tallying tallying(counter, canvas.Width(), canvas.Height(), initial);
  RenderScene(scene, canvas, {}, extensions);
  return tallying.PerPixel();
}

// The cost views of the shadows: the stencil's writes per pixel for the shadow volumes,
// and, per pixel, how many pixels read the same shadow-map entry (grey: no lookup, the
// sky), each with its totals said once drawn.
std::vector<cgfs::Figure> ShadowCostFigures() {
  const cgfs::CostView writes_view, entries_view;
  const auto stencil_writes = [writes_view](const Scene& scene, Canvas& canvas) {
    const Extensions volumes = With([](Extensions& e) { e.shadows = Shadows::kShadowVolumes; });
    writes_view.Draw(canvas, CountedWhileDrawing(kStencilWrites, 0, scene, canvas, volumes),
                     kStencilWritesScale);
  };
  const auto pixels_per_entry = [entries_view](const Scene& scene, Canvas& canvas) {
    const Extensions maps = With([](Extensions& e) { e.shadows = Shadows::kShadowMaps; });
    const std::vector<cgfs::Count> entries =
        CountedWhileDrawing(kShadowMapEntries, -1, scene, canvas, maps);
    entries_view.Draw(canvas, PixelsSharingEntry(entries), kPixelsPerEntryScale);
  };
  std::vector<cgfs::Figure> figures = {
      SceneFigure("stencil-shadows-stencil-writes",
                  "the stencil's writes per pixel for the shadow volumes, on a scale to 20",
                  SceneShadows, stencil_writes),
      SceneFigure("shadow-map-pixels-per-entry",
                  "pixels reading the same shadow-map entry as each pixel, on a scale to 404",
                  SceneShadows, pixels_per_entry),
  };
  figures[0].measured = writes_view.Measured();
  figures[1].measured = entries_view.Measured();
  return figures;
}

// "Shadows": the passes of Figure 15-3, the volume of Figure 15-4, and one scene lit by
// one light without shadows, with stencil shadows and with shadow maps.
std::vector<cgfs::Figure> ShadowFigures() {
  const auto one_light = [](std::size_t k) {
    return [k] {
      Scene scene = SceneShading();
      scene.lights = {scene.lights[k]};
      return scene;
    };
  };
  const Extensions volumes = With([](Extensions& e) { e.shadows = Shadows::kShadowVolumes; });
  const Extensions maps = With([](Extensions& e) { e.shadows = Shadows::kShadowMaps; });
  const auto volume_edges = [volumes](const Scene& scene, Canvas& canvas) {
    RenderScene(scene, canvas, {}, volumes);
    DrawShadowVolumeEdges(scene, scene.instances.front(), scene.lights.back(), -1, canvas);
  };
  return {
      SceneFigure("fig-15-3a-ambient-pass", "chapter 13's scene lit by its ambient light alone",
                  one_light(0), Extensions{}),
      SceneFigure("fig-15-3b-directional-pass", "lit by its directional light alone", one_light(1),
                  Extensions{}),
      SceneFigure("fig-15-3c-point-pass", "lit by its point light alone", one_light(2),
                  Extensions{}),
      SceneFigure("fig-15-3d-sum-of-passes", "the three passes added up, clamped once: as one pass",
                  SceneShading, With([](Extensions& e) { e.multipass_lighting = true; })),
      SceneFigure(
          "fig-15-4-shadow-volume",
          "a cube's shadow volume for a point light, its edges down to the floor: the shadow",
          SceneCubeOverFloor, volume_edges),
      SceneFigure("no-shadows",
                  "chapter 13's objects over a floor, lit from above left, no shadows",
                  SceneShadows, Extensions{}),
      SceneFigure("stencil-shadows", "the same with stencil shadows (depth fail)", SceneShadows,
                  volumes),
      SceneFigure("shadow-map",
                  "the same with shadow maps, 256 x 256 per view, no filtering: jagged edges",
                  SceneShadows, maps),
      SceneFigure("shadow-map-pcf", "the same with percentage-closer filtering: softer edges",
                  SceneShadows, With([](Extensions& e) {
                    e.shadows = Shadows::kShadowMaps;
                    e.shadow_mapping.percentage_closer_filtering = true;
                  })),
      SceneFigure("camera-in-shadow-depth-fail",
                  "the camera inside a shadow volume: depth fail counts right", SceneCameraInShadow,
                  volumes),
      SceneFigure("camera-in-shadow-depth-pass",
                  "the same counted in front of the surface (depth pass): shadow and light swapped",
                  SceneCameraInShadow, With([](Extensions& e) {
                    e.shadows = Shadows::kShadowVolumes;
                    e.shadow_volume_counting = ShadowVolumeCounting::kDepthPass;
                  })),
      SceneFigure("shadow-map-directional",
                  "a directional light's shadows from one orthographic 512 x 512 map, filtered",
                  SceneShadowsDirectional, With([](Extensions& e) {
                    e.shadows = Shadows::kShadowMaps;
                    e.shadow_mapping.size = 512;
                    e.shadow_mapping.percentage_closer_filtering = true;
                  })),
  };
}

// "Environment Mapping", and every stage at once. The crate and its texture live as
// long as the figures that draw them.
std::vector<cgfs::Figure> EnvironmentFigures(const ChapterSettings& settings) {
  const auto crate_texture = CrateTexture(settings);
  const auto crate = std::make_shared<const Model>(TexturedCube(*crate_texture));
  const auto crates = [crate, crate_texture](Scene (*scene)(const Model&)) {
    return [crate, crate_texture, scene] { return scene(*crate); };
  };
  return {
      SceneFigure(
          "environment-map",
          "a mirror sphere among the crates, reflecting a cube map rendered from its centre",
          crates(SceneMirrorSphere), With([](Extensions& e) { e.environment_mapping = true; })),
      {"cube-map", "that cube map unfolded: +Y; -X, +Z, +X, -Z; -Y",
       [crate, crate_texture](Canvas& canvas) {
         const Scene scene = SceneMirrorSphere(*crate);
         DrawCubeMap(RenderCubeMap(scene, scene.instances.back().transform.translation, 150),
                     canvas);
       }},
      SceneFigure(
          "everything",
          "textures, a normal-mapped floor, a mirror sphere and filtered shadow maps at once",
          crates(SceneEverything), With([](Extensions& e) {
            e.normal_mapping = true;
            e.environment_mapping = true;
            e.shadows = Shadows::kShadowMaps;
            e.shadow_mapping.percentage_closer_filtering = true;
          })),
  };
}

// The reader's model flat-shaded with its triangles' normals; with chapter 14's
// everything; and with filtered shadow maps.
std::vector<cgfs::Figure> ModelFigures(const ChapterSettings& settings) {
  const std::shared_ptr<const std::vector<Model>> model = settings.model;
  const auto textures = settings.model_textures;  // kept as long as the figures
  std::size_t triangles = 0;
  for (const Model& part : *model) {
    triangles += part.triangles.size();
  }
  const std::string about = settings.model_name + ", " + std::to_string(triangles) +
                            " triangles, " +
                            (model->front().closed ? "closed: back faces culled" : "not closed");
  const std::function<Scene()> scene = [model, textures] { return SceneModel(*model); };
  return {
      SceneFigure(
          "model-flat", about + ", flat shading with the triangles' normals", scene,
          [](const Scene& shown, Canvas& canvas) {
            RenderScene(shown, canvas, {ShadingModel::kFlat, NormalSource::kTriangle, {}, {}});
          }),
      SceneFigure("model", about + ", Phong shading, textured perspective-correct, trilinear",
                  scene, Extensions{}),
      SceneFigure("model-shadow-map",
                  about + ", on a floor it casts its shadow on (shadow maps, filtered)", scene,
                  With([](Extensions& e) {
                    e.shadows = Shadows::kShadowMaps;
                    e.shadow_mapping.percentage_closer_filtering = true;
                  })),
  };
}

}  // namespace

std::vector<cgfs::Figure> Figures(const ChapterSettings& settings) {
  if (settings.model) {
    return ModelFigures(settings);
  }
  std::vector<cgfs::Figure> figures = NormalMapFigures();
  for (auto group : {ShadowFigures(), ShadowCostFigures(), EnvironmentFigures(settings)}) {
    figures.insert(figures.end(), group.begin(), group.end());
  }
  cgfs::SetCostView(figures, "stencil-shadows", "stencil-shadows-stencil-writes");
  cgfs::SetCostView(figures, "shadow-map", "shadow-map-pixels-per-entry");
  return figures;
}

std::vector<cgfs::Count> PixelsSharingEntry(const std::vector<cgfs::Count>& entries) {
  std::unordered_map<cgfs::Count, cgfs::Count> readers;
  for (const cgfs::Count entry : entries) {
    readers[entry] += entry >= 0 ? 1 : 0;
  }
  std::vector<cgfs::Count> shared(entries.size(), -1);
  for (std::size_t i = 0; i < entries.size(); ++i) {
    shared[i] = entries[i] >= 0 ? readers[entries[i]] : -1;
  }
  return shared;
}
