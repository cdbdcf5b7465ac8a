// Chapter 14's texturing, timed with Google Benchmark (run by scripts/benchmark): what
// each of the chapter's figures costs at 600x600, on one core (the textures are made
// once, before the timing, as the chapter program makes them).
//
//   Figures/<figure>   e.g. Figures/fig-14-8-close-up-bilinear
#include <benchmark/benchmark.h>

#include "benchmark_main.h"
#include "scenes.h"

namespace {

void Render(benchmark::State& state, const cgfs::Figure& figure) {
  Canvas canvas(600, 600);
  for (auto _ : state) {
    figure.draw(canvas);
    benchmark::DoNotOptimize(canvas);
  }
}

}  // namespace

void RegisterAll() {
  for (const cgfs::Figure& figure : Figures({})) {
    benchmark::RegisterBenchmark(("Figures/" + figure.name).c_str(), Render, figure)
        ->Unit(benchmark::kMillisecond);
  }
}
