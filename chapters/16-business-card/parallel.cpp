#include "parallel.h"

#include <algorithm>
#include <atomic>
#include <exception>
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
  std::vector<std::thread> pool;
  for (int i = 1; i < workers; ++i) {
    pool.emplace_back(guarded);
  }
  guarded();
  for (std::thread& thread : pool) {
    thread.join();
  }
  if (failure) {
    std::rethrow_exception(failure);
  }
}
