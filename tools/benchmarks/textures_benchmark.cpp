// Chapter 14's texturing, timed with Google Benchmark (run by scripts/benchmark): what
// each of the chapter's figures costs at 600x600, on one core (the textures are made
// once, before the timing, as the chapter program makes them).
//
//   Figures/<figure>   e.g. Figures/fig-14-8-close-up-bilinear
#include "benchmark_main.h"
#include "scenes.h"

void RegisterAll() {
  RegisterFigures("Figures", Figures({}));
}
