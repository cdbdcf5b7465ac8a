// --model (options.h): the normals a model file gives, at each corner, in the book's
// coordinates; the triangle's own where it gives none.
#include <catch2/catch.hpp>

#include <glm/geometric.hpp>

#include "options.h"
#include "program/book_model.h"

namespace {

// (V1 - V0) x (V2 - V0) of a triangle, of length 1: outwards (chapter 12's test).
Vec3 OwnNormal(const Model& model, const Triangle& T) {
  const Vec3& A = model.vertices[T.v[0]];
  return glm::normalize(glm::cross(model.vertices[T.v[1]] - A, model.vertices[T.v[2]] - A));
}

}  // namespace

TEST_CASE("a model file's normals are turned with its coordinates", "[model]") {
  // The house's faces are flat and its file gives each face's normal: every corner's
  // normal must be its triangle's own, which points outwards.
  const Model house = ModelFromFile(cgfs::ReadBookModel(CGFS_MODELS_DIR "/house.obj"));
  for (const Triangle& T : house.triangles) {
    for (const Vec3& N : T.normals) {
      CHECK(glm::dot(N, OwnNormal(house, T)) == Approx(1).epsilon(1e-6));
    }
  }
}

TEST_CASE("without normals in the file, each corner has its triangle's own", "[model]") {
  cgfs::ModelFile file = cgfs::ReadModelFile(CGFS_MODELS_DIR "/house.obj");
  file.normals.clear();
  for (cgfs::ModelFile::Face& face : file.faces) {
    for (cgfs::ModelFile::Corner& corner : face.corners) {
      corner.normal = -1;
    }
  }
  const Model house = ModelFromFile(cgfs::InBookCoordinates(file));
  for (const Triangle& T : house.triangles) {
    for (const Vec3& N : T.normals) {
      CHECK(N == OwnNormal(house, T));
    }
  }
}
