// --model and --texture (options.h): a model file's texture coordinates, and its
// triangles parted by texture (a Model has one; cgfs::PaintedParts, tested with the
// library).
#include <catch2/catch.hpp>

#include <CLI/CLI.hpp>

#include "golden.h"
#include "options.h"
#include "program/arguments.h"
#include "program/book_model.h"
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
  const Model house = ModelFromFile(cgfs::InBookCoordinates(House()));
  const Triangle& front = house.triangles[0];
  REQUIRE(house.vertices[front.v[0]] == Vec3(-1, 0, -1));
  CHECK(front.uvs[0] == glm::dvec2(0, 1));
  for (const glm::dvec2& uv : front.uvs) {
    CHECK((uv.y == 0 || uv.y == 1));
  }
}

TEST_CASE("the model figure paints the walls with their texture and the door in its colour",
          "[model]") {
  // As --model gives it: the walls' material names house-bricks.ppm (house.mtl).
  ChapterSettings settings;
  CLI::App app;
  AddChapterOptions(app, settings);
  const char* const argv[] = {"14-textures", "--model", CGFS_MODELS_DIR "/house.obj"};
  REQUIRE(cgfs::ParseArguments(app, 3, argv));
  REQUIRE(settings.model->size() == 2);  // the walls, textured; the roof and the door
  CHECK(settings.model_textures.size() == 1);
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
