// The business card's two speed-ups (chapters/16-business-card/README.md), timed with
// Google Benchmark (run by scripts/benchmark), in wall-clock time since one of them
// is threads:
//   Card/<optimisations>        the card's image, 512x512 at 64 samples per pixel,
//                               with none, bound, threads (one per core) or all
//   Card/stratified             business-card-stratified: 512x512 at 28 low-discrepancy
//                               samples per pixel, all optimisations
//   Quick/<optimisations>       128x128 at 4 samples (what CTest runs, to see it work)
#include <benchmark/benchmark.h>

#include <string>

#include "benchmark_main.h"
#include "render.h"

namespace {

void RenderCard(benchmark::State& state, const std::string& optimizations, int side, int samples,
                bool stratified) {
  RenderSettings settings;
  settings.samples = samples;
  settings.optimizations = OptimizationsNamed({optimizations});
  settings.stratified = stratified;
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
                                 optimizations, kCardSide, kCardSamples, false)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->Iterations(1);
    benchmark::RegisterBenchmark((std::string("Quick/") + optimizations).c_str(), RenderCard,
                                 optimizations, 128, 4, false)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  }
  benchmark::RegisterBenchmark("Card/stratified", RenderCard, "all", kCardSide, kStratifiedSamples,
                               true)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime()
      ->Iterations(1);
}
