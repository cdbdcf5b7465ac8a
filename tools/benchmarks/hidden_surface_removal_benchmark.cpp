// Chapter 12's ways of drawing a scene, timed with Google Benchmark (run by
// scripts/benchmark). Back-face culling is the chapter's optimisation: the book says
// it halves the work; these measure by how much it does.
//
//   Cubes/<method>          Figure 10-10's two cubes at 600x600
//   CubeGrid/<n>/<method>   n x n cubes, one behind the other, at 600x600
#include <benchmark/benchmark.h>

#include <string>
#include <utility>
#include <vector>

#include "benchmark_main.h"
#include "scenes.h"

namespace {

std::vector<std::pair<std::string, HiddenSurfaceRemoval>> Methods() {
  return {
      {"model-order", {.draw_order = DrawOrder::kModelOrder, .cull_back_faces = false}},
      {"painters", {.draw_order = DrawOrder::kPaintersAlgorithm, .cull_back_faces = false}},
      {"depth-buffer", {.cull_back_faces = false}},
      {"depth-buffer-culled", {}},
  };
}

// n x n cubes turned 30 degrees, in rows that go away from the camera, each row as
// wide as the view and partly hidden by the row in front of it.
Scene CubeGrid(int n) {
  Scene scene;
  for (int row = 0; row < n; ++row) {
    const double z = 4 + 2.5 * row;
    for (int column = 0; column < n; ++column) {
      const Vec3 position((column + 0.5 - n / 2.0) * 0.8 * z / n, -1.5 + 0.2 * row, z);
      scene.instances.push_back({&CubeModel(), {0.6, MakeOYRotationMatrix(30), position}});
    }
  }
  return scene;
}

void Render(benchmark::State& state, const Scene& scene, const HiddenSurfaceRemoval& method) {
  Canvas canvas(600, 600);
  for (auto _ : state) {
    RenderScene(scene, canvas, method);
    benchmark::DoNotOptimize(canvas);
  }
}

}  // namespace

void RegisterAll() {
  for (const auto& [name, method] : Methods()) {
    benchmark::RegisterBenchmark(("Cubes/" + name).c_str(), Render, SceneTransformedCubes(), method)
        ->Unit(benchmark::kMillisecond);
  }
  for (const int n : {4, 8}) {
    for (const auto& [name, method] : Methods()) {
      benchmark::RegisterBenchmark(("CubeGrid/" + std::to_string(n) + "/" + name).c_str(), Render,
                                   CubeGrid(n), method)
          ->Unit(benchmark::kMillisecond);
    }
  }
}
