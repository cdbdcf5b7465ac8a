// Counting work beside the book's code, for the views of where the work goes: one line
// at the event, Tally(kCounter) or TallyAt(kCounter, x, y) (or Tally(kCounter, n) for n
// events at once), and nothing in any of the
// book's signatures, structures or scenes (pbrt-v4's per-pixel statistics are the
// model). A counter is declared once, at the top of the file whose code counts it:
//
//   inline constexpr cgfs::Counter kTracedRays{"rays traced"};
//
// Counting is off unless a Tallying is alive; then each event costs one test of a flag.
// A Tallying counts one counter over a canvas's pixels, for one render: an event at a
// canvas point adds one to that pixel's count, an event with no pixel (or off the
// canvas) to the total only. Tally(counter) counts at the pixel the thread draws, as the
// render loop sets it (CurrentPixel). Each pixel is drawn by one thread, so each count is
// added to by one thread only: threads need no lock.
#pragma once

#include <atomic>
#include <cstdint>
#include <vector>

namespace cgfs {

// A count of work: 64 bits on every target (long is 32 bits in WebAssembly, where ten
// thousand spheres tested at every pixel of a 600 x 600 canvas, 3.6 billion, wrapped).
using Count = std::int64_t;

struct Counter {
  const char* name;  // what it counts, in words ("rays traced")
};

class Tallying;

namespace tally_internal {
extern std::atomic<Tallying*> active;  // the one counting, if any
// The pixel this thread draws (CurrentPixel), if one is set.
struct Pixel {
  int x = 0, y = 0;
  bool set = false;
};
inline thread_local Pixel current_pixel;
// The work of an event while something is tallied: out of line and marked cold, so that
// the loops that count keep their registers for their own work.
[[gnu::cold]] void Add(const Counter& counter, int x, int y);
[[gnu::cold]] void AddAtCurrentPixel(const Counter& counter, cgfs::Count events);
[[gnu::cold]] void RecordAtCurrentPixel(const Counter& counter, cgfs::Count value);
}  // namespace tally_internal

// One event at canvas point (x, y).
inline void TallyAt(const Counter& counter, int x, int y) {
  if (tally_internal::active.load(std::memory_order_relaxed) != nullptr) [[unlikely]] {
    tally_internal::Add(counter, x, y);
  }
}

// `events` events (one unless said) at the pixel this thread is drawing.
inline void Tally(const Counter& counter, cgfs::Count events = 1) {
  if (tally_internal::active.load(std::memory_order_relaxed) != nullptr) [[unlikely]] {
    tally_internal::AddAtCurrentPixel(counter, events);
  }
}

// A value at the pixel this thread is drawing (the last one recorded there stays), for
// a counter whose Tallying keeps values rather than counts: value() gives it, and is
// called only while some counter is tallied.
template <typename Value>
inline void Record(const Counter& counter, const Value& value) {
  if (tally_internal::active.load(std::memory_order_relaxed) != nullptr) [[unlikely]] {
    tally_internal::RecordAtCurrentPixel(counter, value());
  }
}

// The pixel this thread draws from here on, for Tally (a render loop sets it for each
// pixel; an event outside any CurrentPixel counts at no pixel).
class CurrentPixel {
 public:
  CurrentPixel(int x, int y) { tally_internal::current_pixel = {x, y, true}; }
  ~CurrentPixel() { tally_internal::current_pixel.set = false; }
  CurrentPixel(const CurrentPixel&) = delete;
  CurrentPixel& operator=(const CurrentPixel&) = delete;
};

// Counts `counter` over a width x height canvas while it lives, each pixel from
// `initial` (or keeps the values Record records); one at a time (a second throws
// std::logic_error).
class Tallying {
 public:
  Tallying(const Counter& counter, int width, int height, cgfs::Count initial = 0);
  ~Tallying();
  Tallying(const Tallying&) = delete;
  Tallying& operator=(const Tallying&) = delete;

  // Each pixel's count, row by row from the top, as the canvas's image keeps its pixels.
  const std::vector<cgfs::Count>& PerPixel() const { return counts_; }
  // Every event, on the canvas or not.
  cgfs::Count Total() const;

 private:
  friend void tally_internal::Add(const Counter&, int, int);
  friend void tally_internal::AddAtCurrentPixel(const Counter&, cgfs::Count);
  friend void tally_internal::RecordAtCurrentPixel(const Counter&, cgfs::Count);
  void Add(int x, int y, cgfs::Count events);
  cgfs::Count* Cell(int x, int y);  // the pixel's count, or nullptr off the canvas

  const Counter* counter_;
  int width_, height_;
  std::vector<cgfs::Count> counts_;
  std::atomic<cgfs::Count> elsewhere_{0};  // events off the canvas or at no pixel
};

}  // namespace cgfs
