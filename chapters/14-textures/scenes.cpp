#include "scenes.h"

#include <algorithm>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "program/cost_view.h"

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

// Figures 14-7 and 14-8: one crate so close that each texel of its texture covers
// many pixels.
Scene SceneCrateCloseUp(const Model& crate) {
  Scene scene;
  scene.instances = {{&crate, {1, MakeOYRotationMatrix(-25), {0.4, 0.2, 3.2}}}};
  scene.lights = ShadingLights();
  return scene;
}

const MipmappedTexture& OneTexelCheckerboard() {
  static const MipmappedTexture checkerboard =
      BuildMipChain(MakeCheckerboard(256, 1, cgfs::kBlack, cgfs::kWhite));
  return checkerboard;
}

// Figure 14-11: a 256x256 checkerboard of one-texel squares on a square facing the
// camera, 128 pixels wide (two texels per pixel), and on a floor going away from it,
// where the texels per pixel grow with the distance. Both should look grey.
Scene SceneMinifiedCheckerboard() {
  static const Model square = [] {
    const std::array<Vec3, 3> toward_camera = {Vec3(0, 0, -1), Vec3(0, 0, -1), Vec3(0, 0, -1)};
    const std::array<glm::dvec2, 3> first = {glm::dvec2(0, 0), glm::dvec2(1, 0), glm::dvec2(1, 1)};
    const std::array<glm::dvec2, 3> second = {glm::dvec2(0, 0), glm::dvec2(1, 1), glm::dvec2(0, 1)};
    Model model;
    // 128 pixels of 600 on a viewport 1 wide at d = 1 is 0.21333 at z = 1, 1.06667 at z = 5.
    const double half = 1.06667 / 2;
    model.vertices = {{-half, half, 0}, {half, half, 0}, {half, -half, 0}, {-half, -half, 0}};
    model.triangles = {{{0, 1, 2}, cgfs::kWhite, toward_camera, first},
                       {{0, 2, 3}, cgfs::kWhite, toward_camera, second}};
    model.closed = false;
    model.texture = &OneTexelCheckerboard();
    return model;
  }();
  static const Model floor = [] {
    const std::array<Vec3, 3> up = {Vec3(0, 1, 0), Vec3(0, 1, 0), Vec3(0, 1, 0)};
    Model model;
    model.vertices = {{-2, 0, 12}, {2, 0, 12}, {2, 0, 2}, {-2, 0, 2}};
    model.triangles = {
        {{0, 1, 2}, cgfs::kWhite, up, {glm::dvec2(0, 0), glm::dvec2(1, 0), glm::dvec2(1, 1)}},
        {{0, 2, 3}, cgfs::kWhite, up, {glm::dvec2(0, 0), glm::dvec2(1, 1), glm::dvec2(0, 1)}}};
    model.closed = false;
    model.texture = &OneTexelCheckerboard();
    return model;
  }();
  Scene scene;
  scene.instances = {
      {&square, {1, glm::dmat4(1.0), {-1.1, 0.9, 5}}},
      {&floor, {1, glm::dmat4(1.0), {0.6, -1, 0}}},
  };
  scene.lights = {{LightType::kAmbient, 1}};
  return scene;
}

Scene SceneModel(const std::vector<Model>& parts) {
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
  scene.lights = ShadingLights();
  const Transform placed{1 / radius, glm::dmat4(1.0), Vec3(0, 0, 3) - centre / radius};
  for (const Model& part : parts) {
    scene.instances.push_back({&part, placed});
  }
  return scene;
}

namespace {

// "Mipmapping", Figure 14-12: the chain's levels side by side, each drawn half as
// large as the one before, level 0 half the canvas wide.
void DrawMipChain(const MipmappedTexture& texture, Canvas& canvas) {
  int left = -canvas.Width() / 2;
  int side = canvas.Width() / 2;
  const int top = canvas.Height() / 2 - 1;
  for (const Texture& level : texture.levels) {
    for (int row = 0; row < side; ++row) {
      for (int column = 0; column < side; ++column) {
        canvas.PutPixel(left + column, top - row,
                        GetTexelNearest(level, (column + 0.5) * level.width / side,
                                        (row + 0.5) * level.height / side));
      }
    }
    left += side;
    side = std::max(1, side / 2);
  }
}

Shading WithTexturing(TextureInterpolation interpolation, TextureFilter filter) {
  Shading shading;
  shading.texturing = {interpolation, filter};
  return shading;
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

// The mip-level view's texture: the levels of `like`, of the same sizes, with every
// texel of level k (k, 1, 0). Lit by an ambient light of 1 alone, a pixel's red channel
// is then the level SampleTexture read it from (green 1: the pixel is textured), the
// classic tinted view with numbers for tints.
std::shared_ptr<const MipmappedTexture> LevelNumbers(const MipmappedTexture& like) {
  auto numbered = std::make_shared<MipmappedTexture>();
  for (std::size_t k = 0; k < like.levels.size(); ++k) {
    const Texture& level = like.levels[k];
    numbered->levels.push_back(
        {level.width, level.height,
         std::vector<Color>(level.texels.size(), Color(static_cast<double>(k), 1, 0))});
  }
  return numbered;
}

// The mip level each pixel of `scene` reads with `shading`, -1 where no texture is
// read: the scene drawn with its models' textures numbered (LevelNumbers), then read back.
std::vector<cgfs::Count> MipLevelsRead(Scene scene, const Shading& shading, Canvas& canvas) {
  std::vector<std::shared_ptr<const MipmappedTexture>> textures;
  std::vector<std::shared_ptr<Model>> models;
  for (Instance& instance : scene.instances) {
    auto model = std::make_shared<Model>(*instance.model);
    if (model->texture != nullptr) {
      textures.push_back(LevelNumbers(*model->texture));
      model->texture = textures.back().get();
    }
    instance.model = model.get();
    models.push_back(std::move(model));
  }
  scene.lights = {{LightType::kAmbient, 1.0, {}, {}}};
  RenderScene(scene, canvas, shading);
  std::vector<cgfs::Count> levels;
  for (int row = 0; row < canvas.Height(); ++row) {
    for (int column = 0; column < canvas.Width(); ++column) {
      const cgfs::Rgb8 pixel = canvas.GetImage().At(column, row);
      levels.push_back(pixel.g == 1 && pixel.b == 0 ? pixel.r : -1);
    }
  }
  return levels;
}

// The mip-level view of a scene drawn with `shading`: the level each pixel reads, on
// the cost ramp from 0 to `scale_max` (program/cost_view.h).
cgfs::Figure MipLevelFigure(const std::string& name, const std::string& caption,
                            std::function<Scene()> scene, const Shading& shading,
                            cgfs::Count scale_max) {
  const cgfs::CostView cost;
  const auto draw = [shading, scale_max, cost](Scene drawn, Canvas& canvas) {
    cost.Draw(canvas, MipLevelsRead(std::move(drawn), shading, canvas), scale_max);
  };
  cgfs::Figure figure{name, caption, [scene, draw](Canvas& canvas) { draw(scene(), canvas); },
                      [scene, draw](Canvas& canvas, const cgfs::View& view) {
                        Scene moved = scene();
                        moved.camera = MovedCamera(moved.camera, view);
                        draw(std::move(moved), canvas);
                      }};
  figure.measured = cost.Measured();
  return figure;
}

}  // namespace

namespace {

// The texture of the close-up: the one the settings give, or the 32x32 level of the
// project's 256x256 crate (every line of it still there, averaged), so that each texel
// covers many pixels.
std::shared_ptr<const MipmappedTexture> CloseUpTexture(const ChapterSettings& settings) {
  if (settings.crate_texture) {
    return settings.crate_texture;
  }
  static const auto small = std::make_shared<const MipmappedTexture>(
      BuildMipChain(BuildMipChain(MakeCrateTexture(256)).levels[3]));
  return small;
}

// The reader's model flat-shaded with its triangles' normals, and with everything:
// Phong shading with the model's normals, textured perspective-correct and trilinear.
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
  return {SceneFigure("model-flat", about + ", flat shading with the triangles' normals", scene,
                      {ShadingModel::kFlat, NormalSource::kTriangle, {}, {}}),
          SceneFigure("model", about + ", Phong shading, textured perspective-correct, trilinear",
                      scene, {})};
}

}  // namespace

std::vector<cgfs::Figure> Figures(const ChapterSettings& settings) {
  if (settings.model) {
    return ModelFigures(settings);
  }
  using enum TextureFilter;
  using enum TextureInterpolation;
  // The models and their textures live as long as the figures that draw them.
  const auto crate_texture = CrateTexture(settings);
  const auto crate = std::make_shared<const Model>(TexturedCube(*crate_texture));
  const auto close_up_texture = CloseUpTexture(settings);
  const auto close_up_crate = std::make_shared<const Model>(TexturedCube(*close_up_texture));
  const std::function<Scene()> crates = [crate, crate_texture] { return SceneCrates(*crate); };
  const std::function<Scene()> close_up = [close_up_crate, close_up_texture] {
    return SceneCrateCloseUp(*close_up_crate);
  };
  const std::function<Scene()> minified = SceneMinifiedCheckerboard;
  std::vector<cgfs::Figure> figures = {
      SceneFigure(
          "fig-14-3-affine",
          "three crates, u and v interpolated linearly: the textures bend along the diagonals",
          crates, WithTexturing(kAffine, kNearest)),
      SceneFigure("fig-14-5-perspective-correct",
                  "the same crates, u/z and v/z interpolated: straight and in perspective", crates,
                  WithTexturing(kPerspectiveCorrect, kNearest)),
      SceneFigure("fig-14-7-close-up-nearest", "a crate up close, nearest texel: blocks", close_up,
                  WithTexturing(kPerspectiveCorrect, kNearest)),
      SceneFigure("fig-14-8-close-up-bilinear", "the same crate, bilinear filtering: smooth",
                  close_up, WithTexturing(kPerspectiveCorrect, kBilinear)),
      SceneFigure(
          "fig-14-11-minified-nearest",
          "a one-texel checkerboard made small, nearest texel: noise and patterns, not grey",
          minified, WithTexturing(kPerspectiveCorrect, kNearest)),
      SceneFigure("minified-bilinear", "the same, bilinear: still patterns", minified,
                  WithTexturing(kPerspectiveCorrect, kBilinear)),
      SceneFigure("minified-mipmap", "the same, mipmapping: grey, with steps between the levels",
                  minified, WithTexturing(kPerspectiveCorrect, kMipmap)),
      SceneFigure("minified-trilinear", "the same, trilinear filtering: grey, no steps", minified,
                  WithTexturing(kPerspectiveCorrect, kTrilinear)),
      {"fig-14-12-mip-chain", "the crate texture and its mipmaps, each half the one before",
       [crate_texture](Canvas& canvas) { DrawMipChain(*crate_texture, canvas); }},
      SceneFigure("crates-trilinear", "the crates with everything: perspective-correct, trilinear",
                  crates, Shading{}),
      MipLevelFigure("crates-trilinear-mip-levels",
                     "the mip level each pixel of the crates reads, the nearer of trilinear's two, "
                     "0 to 8",
                     crates, WithTexturing(kPerspectiveCorrect, kMipmap), 8),
  };
  cgfs::SetCostView(figures, "crates-trilinear", "crates-trilinear-mip-levels");
  return figures;
}
