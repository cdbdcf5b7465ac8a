// Chapter 15, "Environment Mapping": the cube map's faces and lookups.
#include <catch2/catch.hpp>

#include "checks.h"
#include "environment_mapping.h"
#include "scenes.h"

using cgfs::test::CheckNear;

TEST_CASE("a direction picks the face of its largest component", "[environment-mapping]") {
  CHECK(CubeMapLookup({0.3, -0.9, 0.2}).face == CubeFace::kNegativeY);
  const CubeMapPoint x = CubeMapLookup({1, 0, 0});
  CHECK(x.face == CubeFace::kPositiveX);
  CHECK(x.s == Approx(0.5));
  CHECK(x.t == Approx(0.5));
  CHECK(CubeMapLookup({0, 0, -2}).face == CubeFace::kNegativeZ);
}

TEST_CASE("on a face, s grows to the right and t downwards", "[environment-mapping]") {
  const CubeMapPoint right = CubeMapLookup({0.5, 0, 1});
  CHECK(right.face == CubeFace::kPositiveZ);
  CHECK(right.s == Approx(0.75));
  CHECK(right.t == Approx(0.5));
  const CubeMapPoint up = CubeMapLookup({0, 0.5, 1});
  CHECK(up.s == Approx(0.5));
  CHECK(up.t == Approx(0.25));
}

TEST_CASE("every face is a view without mirroring, looking along its own axis",
          "[environment-mapping]") {
  for (int f = 0; f < 6; ++f) {
    const auto face = static_cast<CubeFace>(f);
    const glm::dmat4 O = CubeFaceOrientation(face);
    const Vec3 right(O[0]), up(O[1]), forward(O[2]);
    CheckNear(glm::cross(right, up), forward);
    const CubeMapPoint centre = CubeMapLookup(forward);
    CHECK(centre.face == face);
    CHECK(centre.s == Approx(0.5));
    CHECK(centre.t == Approx(0.5));
    // The face's right-hand edge, seen from its centre, is at s = 1.
    CHECK(CubeMapLookup(forward + 0.999 * right).s == Approx(0.9995));
  }
}

TEST_CASE("ReflectRay mirrors a direction about the normal", "[environment-mapping]") {
  CheckNear(ReflectRay({1, 1, 0}, {0, 1, 0}), {-1, 1, 0});
  CheckNear(ReflectRay({0, 0, -1}, {0, 0, -1}), {0, 0, -1});
}

TEST_CASE("a cube map shows what is around its centre, in each direction",
          "[environment-mapping]") {
  // The cube of "Representing a Cube" 5 units along +Z: its blue face (z = -1) faces
  // the centre; ambient light 1 shows the colours as they are.
  Scene scene;
  scene.instances = {{&CubeModel(), {1, glm::dmat4(1.0), {0, 0, 5}}}};
  scene.lights = {{LightType::kAmbient, 1}};
  const CubeMap cube_map = RenderCubeMap(scene, {0, 0, 0}, 32);
  CHECK(SampleCubeMap(cube_map, {0, 0, 1}) == Color(0, 0, 255));
  CHECK(SampleCubeMap(cube_map, {0, 0, -1}) == Color(255, 255, 255));  // the background
  CHECK(SampleCubeMap(cube_map, {1, 0, 0}) == Color(255, 255, 255));
  // Reflective instances are not in the map.
  Model mirror = CubeModel();
  mirror.reflective = 0.5;
  scene.instances[0].model = &mirror;
  CHECK(SampleCubeMap(RenderCubeMap(scene, {0, 0, 0}, 32), {0, 0, 1}) == Color(255, 255, 255));
}

TEST_CASE("SampleCubeMap reads the texels at (s S, t S - 1) of the direction's face",
          "[environment-mapping]") {
  // Faces of 4 x 4 texels; on +Z, texel (i, j) is grey 10 i + j, every other face black.
  // Direction (x, y, 1) is on +Z at s = (x + 1) / 2, t = (1 - y) / 2, read at
  // (4 s, 4 t - 1) = (2 x + 2, 1 - 2 y), bilinear as GetTexel reads.
  CubeMap cube_map;
  for (Texture& face : cube_map.faces) {
    face = {4, 4, std::vector<Color>(16, Color(0, 0, 0))};
  }
  Texture& front = cube_map.faces[static_cast<std::size_t>(CubeFace::kPositiveZ)];
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) {
      front.texels[static_cast<std::size_t>(j * 4 + i)] = Color(10 * i + j);
    }
  }
  CHECK(SampleCubeMap(cube_map, {0, 0, 1}).r == Approx(21));  // (2, 1): a texel itself
  // (1.5, 0.5): texels (1, 0), (2, 0), (1, 1), (2, 1) = 10, 20, 11, 21, halfway: 15.5.
  CHECK(SampleCubeMap(cube_map, {-0.25, 0.25, 1}).r == Approx(15.5));
  // (3, 2.8): 0.2 of texel (3, 2), 0.8 of (3, 3), 32.8. (At y = -1 the direction would
  // be as much -Y as +Z, and a tie goes to the Y faces.)
  CHECK(SampleCubeMap(cube_map, {0.5, -0.9, 1}).r == Approx(32.8));
  CHECK(SampleCubeMap(cube_map, {0, 0, -1}).r == 0);  // the -Z face
}
