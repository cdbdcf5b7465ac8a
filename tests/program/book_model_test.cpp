// A model file in the book's coordinates (program/book_model.h): the one conversion
// behind every chapter's --model, checked on files small enough to work out by hand.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "program/book_model.h"
#include "program/error.h"
#include "temporary_folder.h"

namespace fs = std::filesystem;
using cgfs::BookModel;

namespace {

BookModel FromText(const std::string& text) {
  const fs::path file = cgfs::test::TemporaryFolder("cgfs-book-model-test") / "model.obj";
  std::ofstream(file, std::ios::binary) << text;
  return cgfs::InBookCoordinates(cgfs::ReadModelFile(file));
}

// A tetrahedron wound outwards in OBJ's right-handed coordinates (counter-clockwise
// seen from outside): a closed surface.
const std::string kTetrahedron =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
    "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

}  // namespace

TEST_CASE("a model file in the book's coordinates: z negated, corners turned round",
          "[book-model]") {
  // One triangle in z = 0, facing +z in OBJ (counter-clockwise seen from +z), no
  // normals, texture coordinates at its corners.
  const BookModel model =
      FromText("v 0 0 1\nv 1 0 1\nv 0 1 1\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n");
  REQUIRE(model.vertices.size() == 3);
  CHECK(model.vertices[1] == glm::dvec3(1, 0, -1));  // z negated
  REQUIRE(model.triangles.size() == 1);
  const BookModel::Triangle& T = model.triangles[0];
  CHECK(T.v == std::array<int, 3>{0, 2, 1});  // corners the other way round
  // Its own normal, (V1 - V0) x (V2 - V0) = (0, 1, 0) x (1, 0, 0) = (0, 0, -1): towards
  // the camera, which looks along +z, as the front (+z in OBJ) did.
  for (const glm::dvec3& N : T.normals) {
    CHECK(N == glm::dvec3(0, 0, -1));
  }
  // v counted from the top: the corner at OBJ's (0, 1) is at (0, 0).
  CHECK(T.uvs[0] == glm::dvec2(0, 1));
  CHECK(T.uvs[1] == glm::dvec2(0, 0));
  CHECK(T.uvs[2] == glm::dvec2(1, 1));
  CHECK(T.color == glm::dvec3(200, 200, 200));  // no material: light grey
  CHECK_FALSE(model.closed);                    // one triangle has edges with one side
}

TEST_CASE("the file's normals are kept, in the book's coordinates, made unit length",
          "[book-model]") {
  const BookModel model = FromText(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 2\nvn 0 0 0\n"
      "f 1//1 2//1 3//2\n");
  const BookModel::Triangle& T = model.triangles[0];  // corners 1, 3, 2 of the file
  CHECK(T.normals[0] == glm::dvec3(0, 0, -1));        // (0, 0, 2): z negated, unit length
  CHECK(T.normals[1] == glm::dvec3(0, 0, -1));        // no length: the triangle's own
  CHECK(T.normals[2] == glm::dvec3(0, 0, -1));
}

TEST_CASE("a closed surface is closed, and stays closed when one face is turned over",
          "[book-model]") {
  CHECK(FromText(kTetrahedron).closed);
  std::string turned = kTetrahedron;
  turned.replace(turned.find("f 2 3 4"), 7, "f 2 4 3");
  CHECK_FALSE(FromText(turned).closed);  // two edges now go the same way twice
}

TEST_CASE("a model split into parts keeps only the vertices each part uses", "[book-model]") {
  const BookModel model = FromText(kTetrahedron);
  const std::vector<BookModel> parts = cgfs::SplitModel(model, {1, 0, 1, 1}, 2);
  REQUIRE(parts.size() == 2);
  REQUIRE(parts[0].triangles.size() == 1);
  CHECK(parts[0].vertices.size() == 3);
  CHECK(parts[1].vertices.size() == 4);
  CHECK(parts[1].triangles.size() == 3);
  CHECK(parts[0].closed);  // the model's: a part of a closed surface shows no back face
  // Each part's triangle is the model's, at the same points.
  const BookModel::Triangle& one = parts[0].triangles[0];
  for (std::size_t k = 0; k < 3; ++k) {
    CHECK(parts[0].vertices[static_cast<std::size_t>(one.v[k])] ==
          model.vertices[static_cast<std::size_t>(model.triangles[1].v[k])]);
  }
}

TEST_CASE("a texture larger than the bound is refused in one line, before its texels",
          "[book-model]") {
  const fs::path file = cgfs::test::TemporaryFolder("cgfs-book-model-test") / "wide.ppm";
  std::ofstream(file, std::ios::binary) << "P6\n5 1\n255\n" << std::string(15, '\0');
  CHECK(cgfs::ReadTextureImage(file, 5).Width() == 5);
  CHECK_THROWS_WITH(cgfs::ReadTextureImage(file, 4),
                    Catch::Contains("is 5x1, too large for a texture (at most 4 a side)"));
}

TEST_CASE("a model painted with several textures is one part per texture", "[book-model]") {
  const BookModel house = cgfs::ReadBookModel(CGFS_MODELS_DIR "/house.obj");
  const auto bricks = std::make_shared<const cgfs::Image>(4, 4);
  const std::vector<cgfs::PaintedPart> parts = cgfs::PaintedParts(house, {bricks, {}, {}}, {});
  REQUIRE(parts.size() == 2);
  CHECK(parts[0].texture == bricks);
  CHECK(parts[0].model.triangles.size() == 12);  // the walls
  CHECK(parts[1].texture == nullptr);
  CHECK(parts[1].model.triangles.size() == 16);  // the roof and the door
  CHECK(parts[1].model.vertices.size() == 14);   // only the vertices its triangles use
  // Every triangle of a part is one of the house's, at the same points.
  for (const cgfs::PaintedPart& part : parts) {
    for (const BookModel::Triangle& triangle : part.model.triangles) {
      const auto point = [](const BookModel& model, const BookModel::Triangle& T, std::size_t k) {
        return model.vertices[static_cast<std::size_t>(T.v[k])];
      };
      const auto same = [&](const BookModel::Triangle& each) {
        return each.color == triangle.color && each.uvs == triangle.uvs &&
               point(house, each, 0) == point(part.model, triangle, 0) &&
               point(house, each, 1) == point(part.model, triangle, 1) &&
               point(house, each, 2) == point(part.model, triangle, 2);
      };
      CHECK(std::any_of(house.triangles.begin(), house.triangles.end(), same));
    }
  }
  // One texture everywhere: one part.
  const std::vector<cgfs::PaintedPart> one = cgfs::PaintedParts(house, {bricks, {}, {}}, bricks);
  REQUIRE(one.size() == 1);
  CHECK(one[0].model.triangles.size() == 28);
}
