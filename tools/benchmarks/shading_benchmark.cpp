// Chapter 13's shading models, timed with Google Benchmark (run by scripts/benchmark):
// what each of the chapter's figures costs at 600x600, on one core.
//
//   Figures/<figure>   e.g. Figures/fig-13-1-flat-triangle-normals-diffuse-specular
#include "benchmark_main.h"
#include "scenes.h"

void RegisterAll() {
  RegisterFigures("Figures", Figures());
}
