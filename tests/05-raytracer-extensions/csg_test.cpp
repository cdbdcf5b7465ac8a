// "Constructive Solid Geometry": spans of t combined by union, intersection and
// difference.
#include <catch2/catch.hpp>

#include <memory>

#include "csg.h"
#include "printing.h"
#include "raytracer.h"

namespace {

// Two dummy primitives so that each boundary says where it came from.
const Sphere kA{{0, 0, 0}, 1, cgfs::kRed};
const Sphere kB{{0, 0, 0}, 1, cgfs::kBlue};

std::vector<Span> Spans(const Sphere& sphere, std::initializer_list<std::pair<double, double>> ts) {
  std::vector<Span> spans;
  for (const auto& [in, out] : ts) {
    spans.push_back({{in, &sphere}, {out, &sphere}});
  }
  return spans;
}

}  // namespace

TEST_CASE("CombineSpans: union, intersection and difference of [2, 6] and [4, 8]", "[equations]") {
  const auto a = Spans(kA, {{2, 6}});
  const auto b = Spans(kB, {{4, 8}});

  const auto both = CombineSpans(CsgOperation::kUnion, a, b);
  REQUIRE(both.size() == 1);
  CHECK(both[0].in.t == 2);
  CHECK(both[0].out.t == 8);
  CHECK(both[0].out.primitive == &kB);

  const auto common = CombineSpans(CsgOperation::kIntersection, a, b);
  REQUIRE(common.size() == 1);
  CHECK(common[0].in.t == 4);
  CHECK(common[0].in.primitive == &kB);
  CHECK(common[0].out.t == 6);
  CHECK(common[0].out.primitive == &kA);

  const auto cut = CombineSpans(CsgOperation::kDifference, a, b);
  REQUIRE(cut.size() == 1);
  CHECK(cut[0].in.t == 2);
  CHECK_FALSE(cut[0].in.flip_normal);
  // The ray leaves A - B where it enters B: that surface belongs to B, seen from
  // inside B's hole, so its normal is turned around.
  CHECK(cut[0].out.t == 4);
  CHECK(cut[0].out.primitive == &kB);
  CHECK(cut[0].out.flip_normal);
}

TEST_CASE("CombineSpans: a hole through the middle leaves two spans", "[equations]") {
  const auto cut =
      CombineSpans(CsgOperation::kDifference, Spans(kA, {{2, 8}}), Spans(kB, {{4, 5}}));
  REQUIRE(cut.size() == 2);
  CHECK(cut[0].in.t == 2);
  CHECK(cut[0].out.t == 4);
  CHECK(cut[1].in.t == 5);
  CHECK(cut[1].in.flip_normal);
  CHECK(cut[1].out.t == 8);
}

TEST_CASE("CombineSpans: disjoint spans", "[equations]") {
  const auto a = Spans(kA, {{1, 2}});
  const auto b = Spans(kB, {{3, 4}});
  CHECK(CombineSpans(CsgOperation::kUnion, a, b).size() == 2);
  CHECK(CombineSpans(CsgOperation::kIntersection, a, b).empty());
  const auto cut = CombineSpans(CsgOperation::kDifference, a, b);
  REQUIRE(cut.size() == 1);
  CHECK(cut[0].out.t == 2);
}

TEST_CASE("CsgSolid: the Death Star's crater, hit from the front", "[equations]") {
  // A sphere of radius 2 at z = 10 minus a sphere of radius 1 at z = 8: along the
  // z axis the big one spans [8, 12] and the small one [7, 9], so the first
  // surface is the bottom of the crater at z = 9, on the small sphere, facing -z.
  auto big = std::make_shared<Sphere>(Vec3{0, 0, 10}, 2, cgfs::kRed);
  auto small = std::make_shared<Sphere>(Vec3{0, 0, 8}, 1, cgfs::kBlue);
  const CsgSolid death_star(CsgOperation::kDifference, big, small);
  const Hit hit = death_star.Intersect(Ray{{0, 0, 0}, {0, 0, 1}}, 1, cgfs::kInf);
  CHECK(hit.t == 9);
  CHECK(hit.primitive == small.get());
  CHECK(hit.flip_normal);
  // The small sphere's own normal there is +z; flipped, it faces the camera.
  CHECK(small->Normal({0, 0, 9}) == Vec3(0, 0, 1));
  // Beside the crater, the big sphere's own surface.
  const Hit side = death_star.Intersect(Ray{{0, 0, 0}, {0.15, 0, 1}}, 1, cgfs::kInf);
  CHECK(side.primitive == big.get());
  CHECK_FALSE(side.flip_normal);
}

TEST_CASE("CsgSolid: a nested solid, (A ∪ B) ∩ C", "[equations]") {
  auto a = std::make_shared<Sphere>(Vec3{0, 0, 5}, 1, cgfs::kRed);     // [4, 6]
  auto b = std::make_shared<Sphere>(Vec3{0, 0, 7}, 1, cgfs::kGreen);   // [6, 8]
  auto c = std::make_shared<Sphere>(Vec3{0, 0, 6.5}, 1, cgfs::kBlue);  // [5.5, 7.5]
  const CsgSolid nested(CsgOperation::kIntersection,
                        std::make_shared<CsgSolid>(CsgOperation::kUnion, a, b), c);
  std::vector<Span> spans;
  nested.Spans(Ray{{0, 0, 0}, {0, 0, 1}}, spans);
  REQUIRE(spans.size() == 1);
  CHECK(spans[0].in.t == 5.5);
  CHECK(spans[0].in.primitive == c.get());
  CHECK(spans[0].out.t == 7.5);
  // From t = 6, inside the solid, the next surface is C's far side.
  CHECK(nested.Intersect(Ray{{0, 0, 0}, {0, 0, 1}}, 6, cgfs::kInf).t == 7.5);
}

TEST_CASE("CombineSpans: touching spans join, and a touching intersection is empty",
          "[equations]") {
  const auto a = Spans(kA, {{4, 6}});
  const auto b = Spans(kB, {{6, 8}});
  const auto both = CombineSpans(CsgOperation::kUnion, a, b);
  REQUIRE(both.size() == 1);
  CHECK(both[0].in.t == 4);
  CHECK(both[0].out.t == 8);
  CHECK(CombineSpans(CsgOperation::kIntersection, a, b).empty());
}
