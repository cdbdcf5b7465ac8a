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
    const bool shadowed = InShadow(ToNumber(c.args.at("stored_depth")), ToNumber(c.args.at("depth")),
                                   ToNumber(c.args.at("bias")));
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
