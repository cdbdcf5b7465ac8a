// The business card's two speed-ups (chapters/16-business-card/README.md), timed with
// Google Benchmark (run by scripts/benchmark), in wall-clock time since one of them
// is threads:
//   Card/<optimisations>        the card's image, 512x512 at 64 samples per pixel,
//                               with none, bound, threads (one per core) or all
//   Quick/<optimisations>       128x128 at 4 samples (what CTest runs, to see it work)
#include <benchmark/benchmark.h>

#include <string>

#include "benchmark_main.h"
#include "render.h"

namespace {

void RenderCard(benchmark::State& state, const std::string& optimizations, int side, int samples) {
  RenderSettings settings;
  settings.samples = samples;
  settings.optimizations = OptimizationsNamed({optimizations});
  cgfs::Canvas canvas(side, side);
  for (auto _ : state) {
    Render(canvas, settings);
    benchmark::DoNotOptimize(canvas);
  }
}

}  // namespace

void RegisterAll() {
  for (const char* optimizations : {"none", "bound", "threads", "all"}) {
    benchmark::RegisterBenchmark((std::string("Card/") + optimizations).c_str(), RenderCard,
                                 optimizations, kCardSide, kCardSamples)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->Iterations(1);
    benchmark::RegisterBenchmark((std::string("Quick/") + optimizations).c_str(), RenderCard,
                                 optimizations, 128, 4)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  }
}
