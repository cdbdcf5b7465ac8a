// The chapter's optimisations: every exact one, alone or all together, draws every
// figure byte for byte as without any.
#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <utility>

#include "golden.h"
#include "meshes.h"
#include "printing.h"
#include "scenes.h"

using cgfs::test::FindFigure;
using cgfs::test::IsSameImageAs;

namespace {

cgfs::Image Draw(const std::string& figure, int side, const Optimizations& optimizations) {
  ChapterSettings settings;
  settings.optimizations = optimizations;
  return cgfs::RenderFigure(FindFigure(Figures(settings), figure), side, side).GetImage();
}

}  // namespace

TEST_CASE("OptimizationsNamed: none, all, and lists", "[optimizations]") {
  const Optimizations none = OptimizationsNamed({"none"});
  CHECK(none.threads == 1);
  CHECK_FALSE(none.cache);
  CHECK_FALSE(none.bvh);
  const Optimizations all = OptimizationsNamed({"all"});
  CHECK(all.threads == static_cast<int>(std::max(1U, std::thread::hardware_concurrency())));
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
    // Without the hierarchy the big scenes take a while: drawn small, and only with the
    // switches whose work grows with the scene (the hierarchy, and all of them); the
    // others are as well tested on the smaller scenes. Grazing rays test the hierarchy
    // on them below ("Bvh: grazing rays ...").
    const bool big = figure.name == "sphere-field-10000" || figure.name == "sphere-field-100000" ||
                     figure.name == "torus-mesh";
    const int side = big ? 12 : 64;
    const cgfs::Image plain = Draw(figure.name, side, {});
    for (const auto& [name, optimizations] : switches) {
      if (big && name != "bvh" && name != "all") {
        continue;
      }
      INFO(figure.name << " at " << side << "x" << side << " with " << name);
      CHECK_THAT(Draw(figure.name, side, optimizations), IsSameImageAs(plain));
    }
  }
}

namespace {

// An object every ray meets (its box is everything near the camera) that never shows:
// it only notes which threads ask, and takes a moment to answer, so that every worker
// gets tiles to draw.
class ThreadRecorder final : public Object {
 public:
  Hit Intersect(const Ray&, double, double) const override {
    std::this_thread::sleep_for(std::chrono::microseconds(50));
    const std::lock_guard<std::mutex> lock(mutex_);
    threads_.insert(std::this_thread::get_id());
    return {};
  }
  Vec3 Normal(const Vec3&) const override { return {0, 0, 1}; }
  Box Bounds() const override { return {{-100, -100, -100}, {100, 100, 100}}; }
  std::size_t Threads() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    return threads_.size();
  }

 private:
  mutable std::mutex mutex_;
  mutable std::set<std::thread::id> threads_;
};

}  // namespace

TEST_CASE("RenderScene with all optimisations draws on one worker per core", "[optimizations]") {
  Scene scene;
  const auto recorder = std::make_shared<ThreadRecorder>();
  scene.objects.push_back(recorder);
  Canvas canvas(32, 32);  // 4 tiles
  RenderScene(scene, 0, canvas, AllOptimizations());
  const auto cores = std::max(1U, std::thread::hardware_concurrency());
  CHECK(recorder->Threads() == std::min<std::size_t>(cores, 4));
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

TEST_CASE("IsInShadow: the last blocker shadows only between the point and the light",
          "[optimizations]") {
  // A sphere at z = 10 and a point light at z = 5. From z = 12 the sphere is between
  // the point and the light, and becomes the remembered blocker; from z = -5 it lies
  // beyond the light, where it shadows nothing, remembered or not.
  Scene scene;
  scene.objects.push_back(std::make_shared<Sphere>(Vec3{0, 0, 10}, 1, cgfs::kRed));
  scene.lights.push_back({LightType::kPoint, 1, {0, 0, 5}});
  PrepareScene(scene, AllOptimizations());
  const Vec3 light = scene.lights[0].position;
  const Vec3 behind{0, 0, 12};
  const Vec3 in_front{0, 0, -5};
  CHECK(IsInShadow(behind, light - behind, 1, 0, scene));
  CHECK_FALSE(IsInShadow(in_front, light - in_front, 1, 0, scene));
}
