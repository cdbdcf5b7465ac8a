// The chapter's optimisations: every exact one, alone or all together, draws every
// figure byte for byte as without any.
#include <catch2/catch.hpp>

#include <string>

#include "golden.h"
#include "meshes.h"
#include "printing.h"
#include "scenes.h"

using cgfs::test::FindFigure;

namespace {

cgfs::Image Draw(const std::string& figure, int side, const Optimizations& optimizations) {
  return cgfs::RenderFigure(FindFigure(Figures({optimizations}), figure), side, side).GetImage();
}

}  // namespace

TEST_CASE("OptimizationsNamed: none, all, and lists", "[optimizations]") {
  const Optimizations none = OptimizationsNamed({"none"});
  CHECK(none.threads == 1);
  CHECK_FALSE(none.cache);
  CHECK_FALSE(none.bvh);
  const Optimizations all = OptimizationsNamed({"all"});
  CHECK(all.threads >= 1);
  CHECK(all.cache);
  CHECK(all.shadow_any_hit);
  CHECK(all.shadow_coherence);
  CHECK(all.bvh);
  CHECK_FALSE(all.subsampling);  // approximate, so never part of "all"
  const Optimizations some = OptimizationsNamed({"bvh", "subsampling"});
  CHECK(some.bvh);
  CHECK(some.subsampling);
  CHECK_FALSE(some.cache);
  CHECK(OptimizationsNamed({"all", "subsampling"}).subsampling);  // together
}

TEST_CASE("every exact optimisation draws every figure byte for byte as none does",
          "[optimizations]") {
  std::vector<std::pair<std::string, Optimizations>> switches;
  for (const char* name :
       {"threads", "cache", "shadow-any-hit", "shadow-coherence", "bvh", "all"}) {
    Optimizations optimizations = OptimizationsNamed({name});
    if (optimizations.threads != 1 || std::string(name) == "threads") {
      optimizations.threads = 3;  // more workers than this machine may have cores: the same
    }
    switches.emplace_back(name, optimizations);
  }

  for (const cgfs::Figure& figure : Figures({})) {
    // Without the hierarchy the big scenes take a while: draw them small.
    const bool big = figure.name == "sphere-field-10000" || figure.name == "sphere-field-100000" ||
                     figure.name == "torus-mesh";
    const int side = big ? 20 : 64;
    const cgfs::Image plain = Draw(figure.name, side, {});
    for (const auto& [name, optimizations] : switches) {
      INFO(figure.name << " at " << side << "x" << side << " with " << name);
      CHECK(Draw(figure.name, side, optimizations) == plain);
    }
  }
}

TEST_CASE("Bvh finds what the loop over every object finds", "[optimizations]") {
  // Random rays through the sphere field and the torus, from the camera and from
  // points among the objects: the same object, the same t, the same yes or no.
  for (Scene scene : {SceneSphereField(1000), SceneTorusMesh(), SceneCsgNested()}) {
    // The torus has 102 400 triangles for the loop to go through: fewer rays.
    const int rays = scene.objects.size() > 10000 ? 300 : 3000;
    Scene with_bvh = scene;
    PrepareScene(scene, {});
    Optimizations bvh;
    bvh.bvh = true;
    PrepareScene(with_bvh, bvh);
    Random random(11);
    for (int i = 0; i < rays; ++i) {
      const Vec3 O =
          i % 2 == 0 ? Vec3{0, 0, 0}
                     : Vec3{random.Between(-3, 3), random.Between(-1, 2), random.Between(4, 10)};
      const Vec3 D{random.Between(-1, 1), random.Between(-1, 1), random.Between(-0.5, 1)};
      const double t_max = i % 3 == 0 ? 1.0 : cgfs::kInf;
      const Hit plain = ClosestIntersection(O, D, 0.001, t_max, scene);
      const Hit fast = ClosestIntersection(O, D, 0.001, t_max, with_bvh);
      REQUIRE(plain.object == fast.object);
      REQUIRE(plain.t == fast.t);
      int plain_object = -1;
      int fast_object = -1;
      REQUIRE(AnyIntersection(O, D, 0.001, t_max, scene, plain_object) ==
              AnyIntersection(O, D, 0.001, t_max, with_bvh, fast_object));
      REQUIRE((plain_object >= 0) == (plain.object >= 0));
    }
  }
}

TEST_CASE("IsInShadow: coherence and any-hit give Listing 4-3's answer", "[optimizations]") {
  Scene plain = SceneSphereField(1000);
  Scene fast = plain;
  PrepareScene(plain, {});
  PrepareScene(fast, AllOptimizations());
  Random random(5);
  long shadowed = 0;
  for (int i = 0; i < 5000; ++i) {
    const Vec3 P{random.Between(-3, 3), random.Between(-0.99, 2), random.Between(5, 12)};
    const Vec3 L = Vec3{2, 1, 0} - P;  // towards the point light
    const bool expected = ClosestIntersection(P, L, plain.epsilon, 1, plain).object >= 0;
    REQUIRE(IsInShadow(P, L, 1, 1, plain) == expected);
    REQUIRE(IsInShadow(P, L, 1, 1, fast) == expected);
    shadowed += expected;
  }
  CHECK(shadowed > 500);  // the test sees both answers
  CHECK(shadowed < 4500);
}
