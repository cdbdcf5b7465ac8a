// Chapter 15, "Normal Mapping": decoding, the tangent basis, and bending the normal.
#include <catch2/catch.hpp>

#include "cases.h"
#include "checks.h"
#include "normal_mapping.h"
#include "scenes.h"

using cgfs::test::CheckNear;

TEST_CASE("DecodeNormal: the cases of 15-rasterizer-extensions.json", "[normal-mapping]") {
  for (const cgfs::test::FunctionCase& c :
       cgfs::test::CasesOf("15-rasterizer-extensions.json", "DecodeNormal")) {
    INFO(c.Describe());
    const Vec3 n = DecodeNormal(cgfs::test::ToColor(c.args.at("texel")));
    CHECK_THAT(cgfs::test::AsNumbers(n), cgfs::test::MatchesCase(c));
  }
}

TEST_CASE("ApplyNormalMap: the cases of 15-rasterizer-extensions.json", "[normal-mapping]") {
  using cgfs::test::ToVector;
  for (const cgfs::test::FunctionCase& c :
       cgfs::test::CasesOf("15-rasterizer-extensions.json", "ApplyNormalMap")) {
    INFO(c.Describe());
    const nlohmann::json& basis = c.args.at("basis");
    const Vec3 bent = ApplyNormalMap(ToVector(c.args.at("n")),
                                     TangentBasis{ToVector(basis.at("T")), ToVector(basis.at("B"))},
                                     ToVector(c.args.at("N")));
    CHECK_THAT(cgfs::test::AsNumbers(bent), cgfs::test::MatchesCase(c));
  }
}

TEST_CASE("a normal map's flat texel decodes to the unbent normal", "[normal-mapping]") {
  CheckNear(DecodeNormal({128, 128, 255}), {0.0039216, 0.0039216, 1.0}, 1e-6);
}

TEST_CASE("a texel of full red decodes to a normal tilted fully along the tangent",
          "[normal-mapping]") {
  CheckNear(glm::normalize(DecodeNormal({255, 128, 128})), {0.99998, 0.0039215, 0.0039215}, 1e-5);
}

TEST_CASE("n = (0, 0, 1) is the surface's own normal, whatever the tangents", "[normal-mapping]") {
  const TangentBasis basis{{1, 0, 0}, {0, 1, 0}};
  CheckNear(ApplyNormalMap({0, 0, 1}, basis, {0, 0, -1}), {0, 0, -1});
  // Tangents that are neither unit nor perpendicular to N are straightened first.
  CheckNear(ApplyNormalMap({0, 0, 1}, {{3, 0, 1}, {0, 2, 1}}, {0, 0, -1}), {0, 0, -1});
  CheckNear(ApplyNormalMap({1, 0, 0}, {{3, 0, 1}, {0, 2, 1}}, {0, 0, -1}), {1, 0, 0});
}

TEST_CASE("the tangent and bitangent point where u and v grow", "[normal-mapping]") {
  // A square facing the camera at z = 5, (u, v) = (0, 0) at its top-left corner and
  // v growing downwards: T along +x, B along -y.
  const TangentBasis basis =
      ComputeTangentBasis({Vec3(-1, 1, 5), Vec3(1, 1, 5), Vec3(1, -1, 5)},
                          {glm::dvec2(0, 0), glm::dvec2(1, 0), glm::dvec2(1, 1)});
  CheckNear(basis.T, {2, 0, 0});
  CheckNear(basis.B, {0, -2, 0});
  // A tilted normal-map normal turns with them: towards +x and -y.
  const Vec3 N = ApplyNormalMap(glm::normalize(Vec3(1, 1, 1)), basis, {0, 0, -1});
  CheckNear(N, glm::normalize(Vec3(1, -1, -1)));
}

TEST_CASE("texture coordinates on a line give no tangent basis, and the default",
          "[normal-mapping]") {
  const TangentBasis basis =
      ComputeTangentBasis({Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(0, 1, 1)},
                          {glm::dvec2(0, 0), glm::dvec2(1, 1), glm::dvec2(2, 2)});
  CheckNear(basis.T, {1, 0, 0});
  CheckNear(basis.B, {0, 1, 0});
}

TEST_CASE("the diamond normal map: flat between the bumps, leaning on their faces",
          "[normal-mapping]") {
  const Texture map = MakeDiamondNormalMap(256, 8);  // cells of 32 x 32 texels
  REQUIRE(map.width == 256);
  REQUIRE(map.texels.size() == 256u * 256u);
  CHECK(map.At(0, 0) == Color(128, 128, 255));  // a cell's corner: flat
  // Left of a bump's centre and above it: leaning towards -u and -v.
  const Vec3 upper_left = glm::normalize(DecodeNormal(map.At(16 - 8, 16 - 2)));
  CHECK(upper_left.x < -0.4);
  CHECK(upper_left.y < -0.4);
  // Right of it and below: towards +u and +v.
  const Vec3 lower_right = glm::normalize(DecodeNormal(map.At(16 + 8, 16 + 2)));
  CHECK(lower_right.x > 0.4);
  CHECK(lower_right.y > 0.4);
}
