// Chapter 15, "Shadow Mapping": the comparison, filtering, and maps of a small scene.
#include <catch2/catch.hpp>

#include "cases.h"
#include "scenes.h"
#include "shadow_mapping.h"

TEST_CASE("InShadow: the cases of 15-rasterizer-extensions.json", "[shadow-mapping]") {
  using cgfs::test::ToNumber;
  for (const cgfs::test::FunctionCase& c :
       cgfs::test::CasesOf("15-rasterizer-extensions.json", "InShadow")) {
    INFO(c.Describe());
    const bool shadowed = InShadow(ToNumber(c.args.at("stored_depth")),
                                   ToNumber(c.args.at("depth")), ToNumber(c.args.at("bias")));
    CHECK_THAT(cgfs::test::AsNumbers(shadowed ? 1.0 : 0.0), cgfs::test::MatchesCase(c));
  }
}

TEST_CASE("PercentageCloserFilter: the cases of 15-rasterizer-extensions.json",
          "[shadow-mapping]") {
  using cgfs::test::ToNumber;
  for (const cgfs::test::FunctionCase& c :
       cgfs::test::CasesOf("15-rasterizer-extensions.json", "PercentageCloserFilter")) {
    INFO(c.Describe());
    const std::array<bool, 4> in_shadow = c.args.at("in_shadow").get<std::array<bool, 4>>();
    const double visibility =
        PercentageCloserFilter(in_shadow, ToNumber(c.args.at("fx")), ToNumber(c.args.at("fy")));
    CHECK_THAT(cgfs::test::AsNumbers(visibility), cgfs::test::MatchesCase(c));
  }
}

TEST_CASE("a point is in shadow when the map holds something closer", "[shadow-mapping]") {
  CHECK(InShadow(3.0, 5.0, 0.05));
  CHECK_FALSE(InShadow(5.0, 5.0, 0.05));   // itself
  CHECK_FALSE(InShadow(4.97, 5.0, 0.05));  // within the bias
  CHECK_FALSE(InShadow(6.0, 5.0, 0.05));
}

TEST_CASE("percentage-closer filtering weighs the four comparisons", "[shadow-mapping]") {
  // Top-left, top-right, bottom-left, bottom-right.
  CHECK(PercentageCloserFilter({true, true, false, false}, 0.5, 0.5) == Approx(0.5));
  CHECK(PercentageCloserFilter({true, false, true, false}, 0.5, 0.5) == Approx(0.5));
  CHECK(PercentageCloserFilter({true, false, true, false}, 0.25, 0.5) == Approx(0.25));
  CHECK(PercentageCloserFilter({false, false, false, false}, 0.3, 0.8) == Approx(1));
  CHECK(PercentageCloserFilter({true, true, true, true}, 0.3, 0.8) == Approx(0));
}

namespace {

// A floor at y = 0 and a cube floating over it (y from 1 to 3).
Scene FloorAndCube() {
  static const Model floor = [] {
    const std::array<Vec3, 3> up = {Vec3(0, 1, 0), Vec3(0, 1, 0), Vec3(0, 1, 0)};
    Model model;
    model.vertices = {{-10, 0, 10}, {10, 0, 10}, {10, 0, -10}, {-10, 0, -10}};
    model.triangles = {{{0, 1, 2}, cgfs::kWhite, up}, {{0, 2, 3}, cgfs::kWhite, up}};
    model.closed = false;
    return model;
  }();
  Scene scene;
  scene.instances = {{&CubeModel(), {1, glm::dmat4(1.0), {0, 2, 0}}}, {&floor, {}}};
  return scene;
}

}  // namespace

TEST_CASE("a point light's six maps find the cube's shadow on the floor", "[shadow-mapping]") {
  ShadowMapping settings;
  settings.size = 128;
  ShadowMap map = RenderShadowMap(FloorAndCube(), {LightType::kPoint, 1, {0, 10, 0}}, settings);
  REQUIRE(map.views.size() == 6);
  const Vec3 up(0, 1, 0);
  CHECK(LightVisibility(map, {0, 0, 0}, up) == 0);  // under the cube
  CHECK(LightVisibility(map, {6, 0, 0}, up) == 1);  // beside it
  CHECK(LightVisibility(map, {0, 3, 0}, up) == 1);  // the cube's top, lit
  CHECK(LightVisibility(map, {0, 0, -6}, up) == 1);
  map.settings.percentage_closer_filtering = true;
  CHECK(LightVisibility(map, {0, 0, 0}, up) == 0);
  CHECK(LightVisibility(map, {6, 0, 0}, up) == 1);
}

TEST_CASE("a directional light's orthographic map does the same", "[shadow-mapping]") {
  ShadowMapping settings;
  settings.size = 128;
  const ShadowMap map =
      RenderShadowMap(FloorAndCube(), {LightType::kDirectional, 1, {}, {0, 1, 0}}, settings);
  REQUIRE(map.views.size() == 1);
  CHECK(map.views[0].orthographic);
  const Vec3 up(0, 1, 0);
  CHECK(LightVisibility(map, {0, 0, 0}, up) == 0);
  CHECK(LightVisibility(map, {0.9, 0, -0.9}, up) == 0);  // still under it
  CHECK(LightVisibility(map, {1.3, 0, 0}, up) == 1);     // straight down, missed
  CHECK(LightVisibility(map, {0, 3, 0}, up) == 1);
  CHECK(RenderShadowMap(FloorAndCube(), {LightType::kAmbient, 1}, settings).views.empty());
}

namespace {

// A directional light's map made by hand: 4 x 4 entries over x and y in [-2, 2] (the
// view's space is the world's), every entry holding z = 100 but entry (2, 1), which holds
// an occluder at z = 1. A point (x, y, z) falls at tx = 4 (x / 2 + 1) / 2 = x + 2 and
// ty = 4 (-y / 2 + 1) / 2 - 1 = 1 - y among the entries (entry (i, j) at the point
// (i, j)); the bias there is one entry (1 unit) for a surface facing the light.
ShadowMap OneOccludedEntry() {
  DepthMap view;
  view.size = 4;
  view.depths.assign(16, 100);
  view.depths[1 * 4 + 2] = 1;
  view.orthographic = true;
  view.half_width = 2;
  ShadowMap map;
  map.views = {view};
  map.light = {LightType::kDirectional, 1, {}, {0, 0, -1}};
  return map;
}

}  // namespace

TEST_CASE("the nearest lookup reads the entry nearest the point, rounded", "[shadow-mapping]") {
  const ShadowMap map = OneOccludedEntry();
  const Vec3 N(0, 0, -1);  // facing the light
  // (tx, ty) = (1.6, 1.3): nearest entry (2, 1), the occluder. Truncated, (1, 1): lit.
  CHECK(LightVisibility(map, {-0.4, -0.3, 10}, N) == 0);
  // (1.4, 1.3): entry (1, 1), lit; (2.4, 0.6): entry (2, 1) again; (2.6, 1.3): (3, 1).
  CHECK(LightVisibility(map, {-0.6, -0.3, 10}, N) == 1);
  CHECK(LightVisibility(map, {0.4, 0.4, 10}, N) == 0);
  CHECK(LightVisibility(map, {0.6, -0.3, 10}, N) == 1);
  // (2, 1.6): entry (2, 2), below the occluder's.
  CHECK(LightVisibility(map, {0, -0.6, 10}, N) == 1);
}

TEST_CASE("percentage-closer filtering reads the four entries around the point",
          "[shadow-mapping]") {
  ShadowMap map = OneOccludedEntry();
  map.settings.percentage_closer_filtering = true;
  const Vec3 N(0, 0, -1);
  // (tx, ty) = (1.6, 1.3): entries (1, 1), (2, 1), (1, 2), (2, 2), fx = 0.6, fy = 0.3; only
  // the top right one (2, 1) is occluded, weighing 0.6 x 0.7 = 0.42: 0.58 of the light.
  CHECK(LightVisibility(map, {-0.4, -0.3, 10}, N) == Approx(0.58));
  // (2.25, 1.5): entries (2, 1) top left ... (3, 2); (2, 1) weighs 0.75 x 0.5.
  CHECK(LightVisibility(map, {0.25, -0.5, 10}, N) == Approx(0.625));
  // (0.5, 0.5): entries (0, 0) ... (1, 1), none occluded.
  CHECK(LightVisibility(map, {-1.5, 0.5, 10}, N) == 1);
}

TEST_CASE("a point light's face and entry: the direction picks the face, then the nearest entry",
          "[shadow-mapping]") {
  // The light at the origin; its +Z face (the view's space is the world's) 4 x 4 entries
  // of 1/z, all empty (0: nothing there) but entry (2, 1), an occluder at z = 0.5. A point
  // (x, 0, 2) is on the +Z face at s = (x / 2 + 1) / 2, tx = 4 s = x + 2, and ty = 4 t - 1 =
  // 1; its entry is one unit wide there (2 z / 4), and so is the bias.
  ShadowMap map;
  map.light = {LightType::kPoint, 1, {0, 0, 0}};
  for (int f = 0; f < 6; ++f) {
    DepthMap face;
    face.size = 4;
    face.depths.assign(16, 0);
    face.world_to_view = MakeCameraMatrix({0, 0, 0}, CubeFaceOrientation(static_cast<CubeFace>(f)));
    map.views.push_back(face);
  }
  map.views[static_cast<std::size_t>(CubeFace::kPositiveZ)].depths[1 * 4 + 2] = 1 / 0.5;
  const Vec3 N(0, 0, -1);
  CHECK(LightVisibility(map, {-0.4, 0, 2}, N) == 0);           // tx = 1.6: entry (2, 1)
  CHECK(LightVisibility(map, {-0.6, 0, 2}, N) == 1);           // tx = 1.4: entry (1, 1)
  CHECK(LightVisibility(map, {-0.4, 0, -2}, {0, 0, 1}) == 1);  // behind: the -Z face, empty
  // ShadowMapEntry names the same entries (view x 16 + row x 4 + column), clamped.
  const long z_face = static_cast<long>(CubeFace::kPositiveZ) * 16;
  CHECK(ShadowMapEntry(map, {-0.4, 0, 2}) == z_face + 1 * 4 + 2);  // tx = 1.6: (2, 1)
  CHECK(ShadowMapEntry(map, {-0.6, 0, 2}) == z_face + 1 * 4 + 1);  // tx = 1.4: (1, 1)
  CHECK(ShadowMapEntry(map, {1.9, 0, 2}) == z_face + 1 * 4 + 3);   // tx = 3.9: clamped to 3
  CHECK(ShadowMapEntry(ShadowMap{}, {0, 0, 2}) == std::nullopt);   // no views: no entry
}
