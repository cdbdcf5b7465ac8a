#include "program/progress_display.h"

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <thread>

#include "cgfs/progress.h"

namespace cgfs {

namespace {

constexpr auto kQuietFor = std::chrono::seconds(1);
constexpr auto kRefreshEvery = std::chrono::milliseconds(250);

}  // namespace

struct ProgressDisplay::State {
  std::string figure;
  std::mutex mutex;
  std::condition_variable finished;
  bool done = false;
  bool shown = false;
  std::thread thread;
};

std::string ProgressDisplay::Line(const std::string& figure, double fraction, double seconds) {
  char text[64];
  if (fraction >= 0) {
    std::snprintf(text, sizeof text, "  %3.0f%%  %.1f s", 100 * fraction, seconds);
  } else {
    std::snprintf(text, sizeof text, "  %.1f s", seconds);
  }
  return "rendering " + figure + text;
}

ProgressDisplay::ProgressDisplay(std::string figure, bool enabled)
    : state_(std::make_unique<State>()) {
  ResetProgress();
  state_->figure = std::move(figure);
  if (!enabled) {
    return;
  }
  state_->thread = std::thread([state = state_.get()] {
    const auto start = std::chrono::steady_clock::now();
    std::unique_lock lock(state->mutex);
    if (state->finished.wait_for(lock, kQuietFor, [&] { return state->done; })) {
      return;
    }
    do {
      const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
      const std::string line = Line(state->figure, ReportedProgress(), elapsed.count());
      std::fprintf(stderr, "\r%s\033[K", line.c_str());
      std::fflush(stderr);
      state->shown = true;
    } while (!state->finished.wait_for(lock, kRefreshEvery, [&] { return state->done; }));
  });
}

ProgressDisplay::~ProgressDisplay() {
  if (state_->thread.joinable()) {
    {
      std::lock_guard lock(state_->mutex);
      state_->done = true;
    }
    state_->finished.notify_one();
    state_->thread.join();
    if (state_->shown) {
      std::fprintf(stderr, "\r\033[K");  // leave the terminal as it was
      std::fflush(stderr);
    }
  }
}

}  // namespace cgfs
