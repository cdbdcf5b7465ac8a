// ReportProgress for the chapters' web pages (common/progress.h), in place of
// common/src/progress.cpp: a figure is drawn on its worker's one thread, where nothing
// could look at a stored fraction while it draws, so each report calls the module's
// onProgress at once (figures_worker.js posts it to the page, throttled).
#include <emscripten.h>

#include "cgfs/progress.h"

// clang-format off
EM_JS(void, CgfsOnProgress, (double fraction), {
  if (Module.onProgress) Module.onProgress(fraction);
});
// clang-format on

namespace cgfs {

namespace {

double reported = -1;

}  // namespace

void ReportProgress(double fraction) {
  reported = fraction;
  CgfsOnProgress(fraction);
}

double ReportedProgress() {
  return reported;
}

void ResetProgress() {
  reported = -1;
}

}  // namespace cgfs
