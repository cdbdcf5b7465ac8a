#include "parallel.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include "cgfs/progress.h"

void ForEachTile(int width, int height, int threads,
                 const std::function<void(const Tile&)>& draw_tile) {
  const int columns = (width + kTileSide - 1) / kTileSide;
  const int rows = (height + kTileSide - 1) / kTileSide;
  const int tiles = columns * rows;
  std::atomic<int> next{0};
  std::atomic<int> done{0};

  auto work = [&] {
    for (int index = next++; index < tiles; index = next++) {
      // Down each column of tiles first: the tiles drawn at the same time are then
      // above one another, and never write to the same cache line of the image.
      const int x = -width / 2 + (index / rows) * kTileSide;
      const int y = -height / 2 + (index % rows) * kTileSide;
      draw_tile({x, std::min(x + kTileSide, width / 2), y, std::min(y + kTileSide, height / 2)});
      cgfs::ReportProgress(static_cast<double>(++done) / tiles);
    }
  };

  const int workers = std::clamp(threads, 1, tiles);
  if (workers == 1) {
    work();
    return;
  }
  // A worker's exception is passed on to the caller once every worker has stopped.
  std::exception_ptr failure;
  std::atomic<bool> failed{false};
  auto guarded = [&] {
    try {
      work();
    } catch (...) {
      if (!failed.exchange(true)) {
        failure = std::current_exception();
      }
      next = tiles;
    }
  };
  // A thread the system cannot start (too many threads, too little memory for their
  // stacks) stops the drawing: the ones already running are told to stop and joined,
  // then it is reported in one line.
  std::vector<std::thread> pool;
  std::string not_started;
  for (int i = 1; i < workers && not_started.empty(); ++i) {
    try {
      pool.emplace_back(guarded);
    } catch (const std::system_error& error) {
      not_started = "cannot start " + std::to_string(workers - 1) + " threads (started " +
                    std::to_string(i - 1) + "): " + error.code().message();
      next = tiles;
    }
  }
  if (not_started.empty()) {
    guarded();
  }
  for (std::thread& thread : pool) {
    thread.join();
  }
  if (!not_started.empty()) {
    throw std::runtime_error(not_started + "; try fewer with --threads");
  }
  if (failure) {
    std::rethrow_exception(failure);
  }
}
