#include "cgfs/progress.h"

#include <atomic>

namespace cgfs {

namespace {

std::atomic<double> reported{-1};

}  // namespace

void ReportProgress(double fraction) {
  reported.store(fraction, std::memory_order_relaxed);
}

double ReportedProgress() {
  return reported.load(std::memory_order_relaxed);
}

void ResetProgress() {
  reported.store(-1, std::memory_order_relaxed);
}

}  // namespace cgfs
