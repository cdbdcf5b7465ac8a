// Chapter 15's stages, timed with Google Benchmark (run by scripts/benchmark): what
// each costs at 600x600 on one core, maps included (they are made for every frame).
//
//   Stages/<figure>   the chapter's figures, each with its stages on
#include <benchmark/benchmark.h>

#include <string>

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
    benchmark::RegisterBenchmark(("Stages/" + figure.name).c_str(), Render, figure)
        ->Unit(benchmark::kMillisecond);
  }
}
