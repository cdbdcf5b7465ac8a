// The chapter's shadows, passes and cube maps against an independent ray caster
// (tests/support): which pixels see the light, and what each face of a cube map shows.
#include <catch2/catch.hpp>

#include <memory>
#include <vector>

#include "figure_checks.h"
#include "golden.h"
#include "scenes.h"

using cgfs::test::Agreement;
using cgfs::test::CastCameraImage;
using cgfs::test::CastCameraOf;
using cgfs::test::CastHit;
using cgfs::test::CastImage;
using cgfs::test::CastScene;
using cgfs::test::CastSceneOf;
using cgfs::test::CompareInstances;
using cgfs::test::Describe;
using cgfs::test::InstanceColoredScene;
using cgfs::test::LabelImage;
using cgfs::test::LabelsOf;
using cgfs::test::RenderFigureNamed;

namespace {

Canvas Render(const Scene& scene, const Extensions& extensions) {
  Canvas canvas(600, 600);
  RenderScene(scene, canvas, {}, extensions);
  return canvas;
}

// Whether the scene's only non-ambient light reaches the point a cast ray hit, and how
// squarely it falls on the surface there (the cosine of its angle with the normal).
struct LightAtHit {
  bool blocked = false;
  double cosine = 0;
};
LightAtHit LightAt(const Scene& scene, const CastScene& cast_scene, const CastHit& hit) {
  for (const Light& light : scene.lights) {
    if (light.type == LightType::kPoint) {
      return {cgfs::test::LightBlocked(cast_scene, hit.point, light.position),
              glm::dot(hit.normal, glm::normalize(light.position - hit.point))};
    }
    if (light.type == LightType::kDirectional) {
      return {cgfs::test::DirectionalLightBlocked(cast_scene, hit.point, light.direction),
              glm::dot(hit.normal, glm::normalize(light.direction))};
    }
  }
  return {};
}

// What the ray caster finds for every pixel of a scene: the point, and whether the
// light reaches it; labels that change at the edges of objects and of shadows.
struct ShadowTruth {
  CastImage cast;
  std::vector<LightAtHit> light;
  LabelImage labels;
};
ShadowTruth CastShadows(const Scene& scene) {
  const CastScene cast_scene = CastSceneOf(scene);
  ShadowTruth truth{CastCameraImage(cast_scene, CastCameraOf(scene), 600, 600), {}, {}};
  truth.light.reserve(truth.cast.hits.size());
  for (const CastHit& hit : truth.cast.hits) {
    truth.light.push_back(hit.instance < 0 ? LightAtHit{} : LightAt(scene, cast_scene, hit));
  }
  std::size_t n = 0;
  truth.labels = LabelsOf(truth.cast, [&](const CastHit& hit) {
    return hit.instance * 2 + (truth.light[n++].blocked ? 1 : 0);
  });
  return truth;
}

// On the pixels more than `margin` pixels from the edge of an object or of a shadow
// whose surface the light meets at less than 78 degrees (so that it makes a visible
// difference): how many are darker in `shadowed` than in `unshadowed` exactly where
// the light is blocked.
Agreement CompareShadows(const ShadowTruth& truth, const Canvas& shadowed, const Canvas& unshadowed,
                         int margin) {
  Agreement agreement;
  for (int y = -300; y < 300; ++y) {
    for (int x = -300; x < 300; ++x) {
      const auto index =
          static_cast<std::size_t>(299 - y) * 600 + static_cast<std::size_t>(x + 300);
      const LightAtHit& light = truth.light[index];
      if (truth.cast.hits[index].instance < 0 || light.cosine < 0.2 ||
          !truth.labels.Inside(x, y, margin)) {
        continue;
      }
      const cgfs::Rgb8 a = shadowed.GetPixel(x, y);
      const cgfs::Rgb8 b = unshadowed.GetPixel(x, y);
      const bool darker = a.r + 2 < b.r || a.g + 2 < b.g || a.b + 2 < b.b;
      ++agreement.counted;
      agreement.agreeing += darker == light.blocked;
    }
  }
  return agreement;
}

Extensions WithShadows(Shadows shadows) {
  Extensions extensions;
  extensions.shadows = shadows;
  return extensions;
}

}  // namespace

TEST_CASE("stencil shadows darken exactly the pixels whose point the light cannot reach",
          "[shadows][ray-cast]") {
  // Exact to the pixel: two pixels of margin, as for the edges of objects.
  const Canvas none = RenderFigureNamed(Figures({}), "no-shadows");
  const ShadowTruth truth = CastShadows(SceneShadows());
  const Agreement stencil =
      CompareShadows(truth, RenderFigureNamed(Figures({}), "stencil-shadows"), none, 2);
  INFO("stencil-shadows: " << Describe(stencil));
  CHECK(stencil.counted > 50000);
  CHECK(stencil.Fraction() >= 0.995);
  const Scene inside = SceneCameraInShadow();
  const ShadowTruth inside_truth = CastShadows(inside);
  const Canvas inside_unshadowed = Render(inside, {});
  const Agreement camera_inside =
      CompareShadows(inside_truth, RenderFigureNamed(Figures({}), "camera-in-shadow-depth-fail"),
                     inside_unshadowed, 2);
  INFO("camera-in-shadow-depth-fail: " << Describe(camera_inside));
  CHECK(camera_inside.Fraction() >= 0.995);
  const Agreement depth_pass =
      CompareShadows(inside_truth, RenderFigureNamed(Figures({}), "camera-in-shadow-depth-pass"),
                     inside_unshadowed, 2);
  INFO("camera-in-shadow-depth-pass: " << Describe(depth_pass));
  CHECK(depth_pass.Fraction() < 0.9);  // the wrong way of counting, shown to be wrong
}

TEST_CASE("shadow maps darken the pixels the light cannot reach, within their entries",
          "[shadows][ray-cast]") {
  // A map's entry covers about five pixels where these shadows fall (256 entries over
  // 90 degrees, 8 units from the light, seen from 6 units away), and the bias moves a
  // shadow's edge by up to a few entries where the light grazes a surface: six pixels
  // of margin from the edge of a shadow.
  const Canvas none = RenderFigureNamed(Figures({}), "no-shadows");
  const ShadowTruth truth = CastShadows(SceneShadows());
  for (const char* name : {"shadow-map", "shadow-map-pcf"}) {
    const Agreement agreement =
        CompareShadows(truth, RenderFigureNamed(Figures({}), name), none, 6);
    INFO(name << ": " << Describe(agreement));
    CHECK(agreement.counted > 50000);
    CHECK(agreement.Fraction() >= 0.995);
  }
  const Scene directional = SceneShadowsDirectional();
  const Agreement agreement = CompareShadows(
      CastShadows(directional), RenderFigureNamed(Figures({}), "shadow-map-directional"),
      Render(directional, {}), 6);
  INFO("shadow-map-directional: " << Describe(agreement));
  CHECK(agreement.Fraction() >= 0.995);
}

TEST_CASE("with every stage on, RenderScene shows what a ray through each pixel meets first",
          "[figures][ray-cast]") {
  const Model crate = TexturedCube(*CrateTexture({}));
  Extensions everything = WithShadows(Shadows::kShadowMaps);
  everything.environment_mapping = true;
  everything.normal_mapping = true;
  for (const Scene& scene : {SceneEverything(crate), SceneShadows(), SceneCameraInShadow()}) {
    const auto cast = CastCameraImage(CastSceneOf(scene), CastCameraOf(scene), 600, 600);
    std::vector<std::unique_ptr<Model>> models;
    const Scene colored = InstanceColoredScene(scene, models);
    for (const Extensions& extensions :
         {everything, WithShadows(Shadows::kShadowVolumes), WithShadows(Shadows::kNone)}) {
      const Agreement agreement = CompareInstances(cast, Render(colored, extensions), 2);
      INFO(Describe(agreement));
      CHECK(agreement.Fraction() >= 0.995);
    }
  }
}

TEST_CASE("each face of a cube map shows what a ray from its centre meets first",
          "[environment][ray-cast]") {
  // The mirror's surroundings, each instance in its own colour: the crate a little
  // more than one unit from the centre must be whole, and every column of every face
  // drawn.
  const Model crate = TexturedCube(*CrateTexture({}));
  const Scene scene = SceneMirrorSphere(crate);
  std::vector<std::unique_ptr<Model>> models;
  const Scene colored = InstanceColoredScene(scene, models);
  const Vec3 centre = scene.instances.back().transform.translation;
  constexpr int kSize = 128;
  const CubeMap cube_map = RenderCubeMap(colored, centre, kSize);
  const CastScene cast_scene = CastSceneOf(scene);
  for (int f = 0; f < 6; ++f) {
    // The face's view: its camera at the centre, the viewport 2d x 2d at d.
    const double d = NearPlaneOfMaps(scene);
    const cgfs::test::CastCamera camera{
        centre, glm::dmat3(CubeFaceOrientation(static_cast<CubeFace>(f))), 2 * d, 2 * d, d};
    const CastImage cast = CastCameraImage(cast_scene, camera, kSize, kSize);
    Canvas face(kSize, kSize);
    const Texture& texture = cube_map.faces[static_cast<std::size_t>(f)];
    for (int row = 0; row < kSize; ++row) {
      for (int column = 0; column < kSize; ++column) {
        face.PutPixel(column - kSize / 2, kSize / 2 - 1 - row, texture.At(column, row));
      }
    }
    const Agreement agreement = CompareInstances(cast, face, 2);
    INFO("face " << f << ": " << Describe(agreement));
    CHECK(agreement.counted > 1000);
    CHECK(agreement.Fraction() >= 0.995);
  }
}
