// --model and --texture (options.h): a model file's texture coordinates, and its
// triangles parted by texture (a Model has one).
#include <catch2/catch.hpp>

#include <algorithm>
#include <memory>

#include "golden.h"
#include "options.h"
#include "program/model_file.h"
#include "scenes.h"

using cgfs::test::RenderFigureNamed;

namespace {

cgfs::ModelFile House() {
  return cgfs::ReadModelFile(CGFS_MODELS_DIR "/house.obj");
}

}  // namespace

TEST_CASE("a model file's texture coordinates count v down from the top", "[model]") {
  // The front wall's first triangle: OBJ's (u, v) = (0, 0) at its bottom left corner is
  // the texture's bottom left, (0, 1) here.
  const Model house = ModelFromFile(House());
  const Triangle& front = house.triangles[0];
  REQUIRE(house.vertices[front.v[0]] == Vec3(-1, 0, -1));
  CHECK(front.uvs[0] == glm::dvec2(0, 1));
  for (const glm::dvec2& uv : front.uvs) {
    CHECK((uv.y == 0 || uv.y == 1));
  }
}

TEST_CASE("a model painted with several textures is one Model per texture", "[model]") {
  const cgfs::ModelFile file = House();
  const Model house = ModelFromFile(file);
  const MipmappedTexture bricks = BuildMipChain(MakeCheckerboard(4, 1, {0, 0, 0}, {255, 0, 0}));
  const std::vector<Model> parts = PaintedParts(house, file, {&bricks, nullptr, nullptr}, nullptr);
  REQUIRE(parts.size() == 2);
  CHECK(parts[0].texture == &bricks);
  CHECK(parts[0].triangles.size() == 12);  // the walls
  CHECK(parts[1].texture == nullptr);
  CHECK(parts[1].triangles.size() == 16);  // the roof and the door
  // Each part keeps only the vertices its triangles use: its triangles are the house's.
  CHECK(parts[1].vertices.size() == 14);
  for (const Model& part : parts) {
    for (const Triangle& triangle : part.triangles) {
      const auto same = [&](const Triangle& each) {
        return each.color == triangle.color && each.uvs == triangle.uvs &&
               house.vertices[each.v[0]] == part.vertices[triangle.v[0]] &&
               house.vertices[each.v[1]] == part.vertices[triangle.v[1]] &&
               house.vertices[each.v[2]] == part.vertices[triangle.v[2]];
      };
      CHECK(std::any_of(house.triangles.begin(), house.triangles.end(), same));
    }
  }
  const std::vector<Model> one = PaintedParts(house, file, {&bricks, nullptr, nullptr}, &bricks);
  REQUIRE(one.size() == 1);
  CHECK(one[0].triangles.size() == 28);
}

TEST_CASE("the model figure paints the walls with their texture and the door in its colour",
          "[model]") {
  ChapterSettings settings;
  const cgfs::ModelFile file = House();
  auto bricks = std::make_shared<const MipmappedTexture>(
      BuildMipChain(LoadTexture(CGFS_MODELS_DIR "/house-bricks.ppm")));
  settings.model = std::make_shared<const std::vector<Model>>(
      PaintedParts(ModelFromFile(file), file, {bricks.get(), nullptr, nullptr}, nullptr));
  settings.model_textures = {bricks};
  settings.model_name = "house.obj";
  const Canvas drawn = RenderFigureNamed(Figures(settings), "model");
  // The door, lit: its colour (89, 51, 25) times the light, in the same proportions.
  const Rgb8 door = drawn.GetPixel(0, -100);
  CHECK(door.r > door.g);
  CHECK(door.g > door.b);
  // The wall's bottom row is the texture's: mortar, light grey; its top row brick red.
  const Rgb8 bottom = drawn.GetPixel(-100, -139);
  const Rgb8 top = drawn.GetPixel(-100, 20);
  CHECK(bottom.g > 0.8 * bottom.r);
  CHECK(top.g < 0.6 * top.r);
}
