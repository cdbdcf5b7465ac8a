// The tally (cgfs/tally.h): counts at canvas points and at the pixel a thread draws,
// only the counter being tallied, only while a Tallying lives, one at a time, and from
// many threads at once without a lock.
#include "cgfs/tally.h"

#include <thread>
#include <vector>

#include <catch2/catch.hpp>

namespace {

constexpr cgfs::Counter kCounted{"counted"};
constexpr cgfs::Counter kOther{"other"};

}  // namespace

TEST_CASE("TallyAt counts at its canvas point, off the canvas in the total only", "[tally]") {
  cgfs::TallyAt(kCounted, 0, 0);  // no Tallying: nothing happens
  const cgfs::Tallying tallying(kCounted, 4, 2);
  cgfs::TallyAt(kCounted, -2, 0);  // column 0, row 0
  cgfs::TallyAt(kCounted, 1, -1);  // column 3, row 1
  cgfs::TallyAt(kCounted, 1, -1);
  cgfs::TallyAt(kCounted, 2, 0);  // off the canvas
  cgfs::TallyAt(kOther, -2, 0);   // another counter: not this one's
  CHECK(tallying.PerPixel() == std::vector<cgfs::Count>{1, 0, 0, 0, 0, 0, 0, 2});
  CHECK(tallying.Total() == 4);
}

TEST_CASE("Tally counts at the pixel the thread draws, or in the total when it draws none",
          "[tally]") {
  const cgfs::Tallying tallying(kCounted, 4, 2);
  {
    const cgfs::CurrentPixel pixel(-1, -1);  // column 1, row 1
    cgfs::Tally(kCounted);
    cgfs::Tally(kCounted);
  }
  cgfs::Tally(kCounted);  // no current pixel
  CHECK(tallying.PerPixel() == std::vector<cgfs::Count>{0, 0, 0, 0, 0, 2, 0, 0});
  CHECK(tallying.Total() == 3);
}

TEST_CASE("Tally counts several events at once", "[tally]") {
  const cgfs::Tallying tallying(kCounted, 2, 2);
  const cgfs::CurrentPixel pixel(0, 0);  // column 1, row 0
  cgfs::Tally(kCounted, 4);
  CHECK(tallying.PerPixel() == std::vector<cgfs::Count>{0, 4, 0, 0});
}

TEST_CASE("counts past 2^31 are kept whole (64 bits on every target, WebAssembly too)", "[tally]") {
  static_assert(sizeof(cgfs::Count) == 8);
  const cgfs::Tallying tallying(kCounted, 2, 2);
  const cgfs::CurrentPixel pixel(0, 0);  // column 1, row 0
  cgfs::Tally(kCounted, 3'000'000'000);
  cgfs::Tally(kCounted, 600'360'000);
  CHECK(tallying.PerPixel() == std::vector<cgfs::Count>{0, 3'600'360'000, 0, 0});
  CHECK(tallying.Total() == 3'600'360'000);
}

TEST_CASE("Record keeps the last value at the pixel drawn, the rest from the start value",
          "[tally]") {
  int asked = 0;
  const auto value = [&asked](cgfs::Count v) {
    return [&asked, v] {
      ++asked;
      return v;
    };
  };
  cgfs::Record(kCounted, value(7));  // nothing tallied: the value is not even asked for
  CHECK(asked == 0);
  const cgfs::Tallying tallying(kCounted, 2, 2, -1);
  cgfs::Record(kCounted, value(9));  // no pixel drawn: kept nowhere
  {
    const cgfs::CurrentPixel pixel(-1, -1);  // column 0, row 1
    cgfs::Record(kCounted, value(5));
    cgfs::Record(kCounted, value(6));
    cgfs::Record(kOther, value(8));  // another counter's
  }
  CHECK(tallying.PerPixel() == std::vector<cgfs::Count>{-1, -1, 6, -1});
}

TEST_CASE("One Tallying at a time", "[tally]") {
  const cgfs::Tallying first(kCounted, 2, 2);
  CHECK_THROWS_AS(cgfs::Tallying(kOther, 2, 2), std::logic_error);
}

TEST_CASE("Threads drawing pixels of their own tally without a lock", "[tally]") {
  constexpr int kSide = 64, kThreads = 8, kRepeats = 200;
  const cgfs::Tallying tallying(kCounted, kSide, kSide);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([t] {
      // Rows t, t + kThreads, ...: each pixel drawn by one thread, as a render's tiles.
      for (int row = t; row < kSide; row += kThreads) {
        for (int column = 0; column < kSide; ++column) {
          const cgfs::CurrentPixel pixel(column - kSide / 2, kSide / 2 - row - 1);
          for (int i = 0; i < kRepeats; ++i) {
            cgfs::Tally(kCounted);
          }
        }
        cgfs::Tally(kCounted);  // between pixels: the total only, from every thread at once
      }
    });
  }
  for (std::thread& thread : threads) {
    thread.join();
  }
  for (const cgfs::Count count : tallying.PerPixel()) {
    REQUIRE(count == kRepeats);
  }
  CHECK(tallying.Total() == static_cast<cgfs::Count>(kSide) * kSide * kRepeats + kSide);
}
