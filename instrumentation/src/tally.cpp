#include "cgfs/tally.h"

#include <numeric>
#include <optional>
#include <stdexcept>

#include "cgfs/screen.h"

namespace cgfs {

namespace tally_internal {

std::atomic<Tallying*> active{nullptr};

void Add(const Counter& counter, int x, int y) {
  Tallying* tallying = active.load(std::memory_order_acquire);
  if (tallying != nullptr && tallying->counter_ == &counter) {
    tallying->Add(x, y, 1);
  }
}

void AddAtCurrentPixel(const Counter& counter, cgfs::Count events) {
  Tallying* tallying = active.load(std::memory_order_acquire);
  if (tallying == nullptr || tallying->counter_ != &counter) {
    return;
  }
  if (current_pixel.set) {
    tallying->Add(current_pixel.x, current_pixel.y, events);
  } else {
    tallying->elsewhere_.fetch_add(events, std::memory_order_relaxed);
  }
}

void RecordAtCurrentPixel(const Counter& counter, cgfs::Count value) {
  Tallying* tallying = active.load(std::memory_order_acquire);
  if (tallying == nullptr || tallying->counter_ != &counter || !current_pixel.set) {
    return;
  }
  if (cgfs::Count* cell = tallying->Cell(current_pixel.x, current_pixel.y)) {
    *cell = value;
  }
}

}  // namespace tally_internal

Tallying::Tallying(const Counter& counter, int width, int height, cgfs::Count initial)
    : counter_(&counter),
      width_(width),
      height_(height),
      counts_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), initial) {
  Tallying* none = nullptr;
  if (!tally_internal::active.compare_exchange_strong(none, this)) {
    throw std::logic_error("Tallying: one at a time");
  }
}

Tallying::~Tallying() {
  tally_internal::active.store(nullptr);
}

cgfs::Count Tallying::Total() const {
  return std::accumulate(counts_.begin(), counts_.end(), cgfs::Count{0}) + elsewhere_.load();
}

// The canvas's mapping (cgfs/screen.h), so that a count is where its pixel is.
cgfs::Count* Tallying::Cell(int x, int y) {
  const std::optional<ScreenPoint> screen = CanvasToScreen(x, y, width_, height_);
  if (!screen) {
    return nullptr;
  }
  return &counts_[static_cast<std::size_t>(screen->row) * static_cast<std::size_t>(width_) +
                  static_cast<std::size_t>(screen->column)];
}

void Tallying::Add(int x, int y, cgfs::Count events) {
  if (cgfs::Count* cell = Cell(x, y)) {
    *cell += events;
  } else {
    elsewhere_.fetch_add(events, std::memory_order_relaxed);
  }
}

}  // namespace cgfs
