// --model (options.h): a model file drawn by the chapter's own code, checked on the house
// of tests/models/ (closed, wound counter-clockwise seen from outside, as OBJ files are).
#include <catch2/catch.hpp>

#include <memory>

#include <glm/geometric.hpp>

#include "figure_checks.h"
#include "golden.h"
#include "options.h"
#include "program/book_model.h"
#include "scenes.h"

using cgfs::test::Agreement;
using cgfs::test::CastCameraImage;
using cgfs::test::CastCameraOf;
using cgfs::test::CastSceneOf;
using cgfs::test::CompareFamilies;
using cgfs::test::Describe;
using cgfs::test::RenderFigureNamed;

namespace {

cgfs::ModelFile House() {
  return cgfs::ReadModelFile(CGFS_MODELS_DIR "/house.obj");
}

}  // namespace

TEST_CASE("a model file's triangles face outwards in the book's coordinates, and it is closed",
          "[model]") {
  const Model house = ModelFromFile(cgfs::InBookCoordinates(House()));
  REQUIRE(house.triangles.size() == 28);
  CHECK(house.closed);
  // The walls and the roof (the first 16 triangles) around the house's middle; the
  // file's z is negated, so the front wall is at z = -1 and the door before it.
  const Vec3 middle(0, 1, 0);
  for (std::size_t t = 0; t < 16; ++t) {
    const Triangle& T = house.triangles[t];
    const Vec3 &A = house.vertices[T.v[0]], &B = house.vertices[T.v[1]],
               &C = house.vertices[T.v[2]];
    INFO("triangle " << t);
    CHECK(glm::dot(glm::cross(B - A, C - A), (A + B + C) / 3.0 - middle) > 0);
  }
  CHECK(house.vertices[10].z == Approx(-1.06));  // the door's front, nearer the camera
}

TEST_CASE("a model drawn with the depth buffer and culling shows what a ray meets first",
          "[model][ray-cast]") {
  // Each triangle coloured by the way it faces in the file: the front (+z) red, the back
  // green, the rest blue. The ray caster culls a closed model's back faces as the
  // chapter does, so it checks what the depth buffer keeps; the door's colour checks
  // the winding: were the corners not turned round with z, culling would take the red
  // front away and show the green back of the door from inside.
  cgfs::ModelFile file = House();
  file.materials = {
      {"front", {255, 0, 0}, {}}, {"back", {0, 255, 0}, {}}, {"side", {0, 0, 255}, {}}};
  for (cgfs::ModelFile::Face& face : file.faces) {
    const auto P = [&](int k) {
      return file.positions[static_cast<std::size_t>(face.corners[k].position)];
    };
    const double z = glm::cross(P(1) - P(0), P(2) - P(0)).z;
    face.material = z > 1e-9 ? 0 : z < -1e-9 ? 1 : 2;
  }
  ChapterSettings settings;
  settings.model = std::make_shared<const Model>(ModelFromFile(cgfs::InBookCoordinates(file)));
  settings.model_name = "house.obj";
  const Scene scene = SceneModel(*settings.model);
  const auto cast = CastCameraImage(CastSceneOf(scene), CastCameraOf(scene), 600, 600);
  const Canvas drawn = RenderFigureNamed(Figures(settings), "model");
  const Agreement agreement = CompareFamilies(scene, cast, drawn, 2);
  INFO(Describe(agreement));
  CHECK(agreement.counted > 30000);
  CHECK(agreement.Fraction() >= 0.995);
  CHECK(drawn.GetPixel(0, -100) == Rgb8{255, 0, 0});  // the door, in the front's red
}
