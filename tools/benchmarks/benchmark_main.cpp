#include "benchmark_main.h"

#include <benchmark/benchmark.h>

void RegisterFigures(const std::string& group, const std::vector<cgfs::Figure>& figures) {
  for (const cgfs::Figure& figure : figures) {
    benchmark::RegisterBenchmark((group + "/" + figure.name).c_str(), [figure](
                                                                          benchmark::State& state) {
      cgfs::Canvas canvas(600, 600);
      for (auto _ : state) {
        figure.draw(canvas);
        benchmark::DoNotOptimize(canvas);
      }
    })->Unit(benchmark::kMillisecond);
  }
}

int main(int argc, char** argv) {
  RegisterAll();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) {
    return 1;
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
