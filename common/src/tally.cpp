#include "cgfs/tally.h"

#include <numeric>
#include <optional>
#include <stdexcept>

namespace cgfs {

namespace {

struct Point {
  int x, y;
};
thread_local std::optional<Point> current_pixel;

}  // namespace

namespace tally_internal {

std::atomic<Tallying*> active{nullptr};

void Add(const Counter& counter, int x, int y) {
  Tallying* tallying = active.load(std::memory_order_acquire);
  if (tallying != nullptr && tallying->counter_ == &counter) {
    tallying->Add(x, y);
  }
}

void AddAtCurrentPixel(const Counter& counter) {
  Tallying* tallying = active.load(std::memory_order_acquire);
  if (tallying == nullptr || tallying->counter_ != &counter) {
    return;
  }
  if (current_pixel) {
    tallying->Add(current_pixel->x, current_pixel->y);
  } else {
    tallying->elsewhere_.fetch_add(1, std::memory_order_relaxed);
  }
}

}  // namespace tally_internal

CurrentPixel::CurrentPixel(int x, int y) {
  current_pixel = Point{x, y};
}

CurrentPixel::~CurrentPixel() {
  current_pixel.reset();
}

Tallying::Tallying(const Counter& counter, int width, int height)
    : counter_(&counter),
      width_(width),
      height_(height),
      counts_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0) {
  Tallying* none = nullptr;
  if (!tally_internal::active.compare_exchange_strong(none, this)) {
    throw std::logic_error("Tallying: one at a time");
  }
}

Tallying::~Tallying() {
  tally_internal::active.store(nullptr);
}

long Tallying::Total() const {
  return std::accumulate(counts_.begin(), counts_.end(), 0L) + elsewhere_.load();
}

// The canvas's mapping (Canvas::ToScreen): column Cw/2 + x, row Ch/2 - y - 1.
void Tallying::Add(int x, int y) {
  const int column = width_ / 2 + x;
  const int row = height_ / 2 - y - 1;
  if (column < 0 || column >= width_ || row < 0 || row >= height_) {
    elsewhere_.fetch_add(1, std::memory_order_relaxed);
    return;
  }
  ++counts_[static_cast<std::size_t>(row) * static_cast<std::size_t>(width_) +
            static_cast<std::size_t>(column)];
}

}  // namespace cgfs
