// The card's switches: `all` is every one of them, with one worker per core, and the
// workers really draw side by side.
#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <mutex>
#include <set>
#include <thread>

#include "optimizations.h"
#include "parallel.h"

namespace {

int Cores() {
  return static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
}

}  // namespace

TEST_CASE("OptimizationsNamed: none, all, and each switch", "[optimizations]") {
  CHECK(OptimizationsNamed({"none"}).threads == 1);
  CHECK_FALSE(OptimizationsNamed({"none"}).bound);
  CHECK(OptimizationsNamed({"all"}).threads == Cores());
  CHECK(OptimizationsNamed({"all"}).bound);
  CHECK(OptimizationsNamed({"threads"}).threads == Cores());
  CHECK_FALSE(OptimizationsNamed({"threads"}).bound);
  CHECK(OptimizationsNamed({"bound"}).threads == 1);
  CHECK(OptimizationsNamed({"bound"}).bound);
}

TEST_CASE("ForEachTile: every tile once, from as many workers as asked", "[optimizations]") {
  // 4 tiles of a 32 x 32 canvas; each takes a moment, so every worker gets one.
  std::mutex mutex;
  std::set<std::thread::id> workers;
  std::multiset<int> tiles;
  ForEachTile(32, 32, Cores(), [&](const Tile& tile) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    const std::lock_guard<std::mutex> lock(mutex);
    workers.insert(std::this_thread::get_id());
    tiles.insert(tile.x_begin * 100 + tile.y_begin);
  });
  CHECK(tiles == std::multiset<int>{-1616, -1600, -16, 0});
  CHECK(static_cast<int>(workers.size()) == std::min(Cores(), 4));
}
