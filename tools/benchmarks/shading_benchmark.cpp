// Chapter 13's shading models, timed with Google Benchmark (run by scripts/benchmark):
// how much each costs on the chapter's scene at 600x600, on one core.
//
//   Shading/<model>       Figures 13-1 to 13-9's scene, model normals, diffuse + specular
//   RaytracerSpheres      Figure 13-11 (Phong)
#include <benchmark/benchmark.h>

#include <string>
#include <utility>

#include "benchmark_main.h"
#include "scenes.h"

namespace {

void Render(benchmark::State& state, const Scene& scene, const Shading& shading) {
  Canvas canvas(600, 600);
  for (auto _ : state) {
    RenderScene(scene, canvas, {}, shading);
    benchmark::DoNotOptimize(canvas);
  }
}

}  // namespace

void RegisterAll() {
  for (const auto& [name, model] :
       {std::pair{"flat", ShadingModel::kFlat}, std::pair{"gouraud", ShadingModel::kGouraud},
        std::pair{"phong", ShadingModel::kPhong}}) {
    benchmark::RegisterBenchmark((std::string("Shading/") + name).c_str(), Render, SceneShading(),
                                 Shading{model, NormalSource::kModel, {}})
        ->Unit(benchmark::kMillisecond);
  }
  benchmark::RegisterBenchmark("RaytracerSpheres", Render, SceneRaytracerSpheres(), Shading{})
      ->Unit(benchmark::kMillisecond);
}
