// --model (options.h): a model file's triangles as the chapter's Triangle objects,
// facing outwards, and drawn through the hierarchy exactly as without it.
#include <catch2/catch.hpp>

#include <memory>

#include <glm/geometric.hpp>

#include "golden.h"
#include "options.h"
#include "program/book_model.h"
#include "scenes.h"

namespace {

ChapterSettings WithHouse(const Optimizations& optimizations) {
  ChapterSettings settings;
  settings.optimizations = optimizations;
  settings.model = std::make_shared<const std::vector<Triangle>>(
      TrianglesFromFile(cgfs::ReadBookModel(CGFS_MODELS_DIR "/house.obj")));
  settings.model_name = "house.obj";
  return settings;
}

}  // namespace

TEST_CASE("a model file's triangles face outwards in the book's coordinates", "[model]") {
  const std::vector<Triangle> house = *WithHouse(AllOptimizations()).model;
  REQUIRE(house.size() == 28);
  // The walls and the roof, the first 16, around the house's middle (the file's z
  // negated: the front wall is at z = -1).
  for (std::size_t t = 0; t < 16; ++t) {
    const Triangle& T = house[t];
    INFO("triangle " << t);
    CHECK(glm::dot(T.N, (T.A + T.B + T.C) / 3.0 - Vec3(0, 1, 0)) > 0);
  }
}

TEST_CASE("a model is drawn through the hierarchy exactly as without it", "[model]") {
  Optimizations none{};
  none.threads = 1;
  const auto draw = [](const Optimizations& optimizations) {
    const ChapterSettings settings = WithHouse(optimizations);
    return cgfs::RenderFigure(cgfs::test::FindFigure(Figures(settings), "model"), 120, 120)
        .GetImage();
  };
  const cgfs::Image plain = draw(none);
  CHECK_THAT(draw(AllOptimizations()), cgfs::test::IsSameImageAs(plain));
  // The door faces the camera, lit: brown, red over green over blue.
  const cgfs::Rgb8 door = plain.At(60, 80);
  CHECK(door.r > door.g);
  CHECK(door.g > door.b);
}
