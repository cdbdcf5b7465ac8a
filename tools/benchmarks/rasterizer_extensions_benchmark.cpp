// Chapter 15's stages, timed with Google Benchmark (run by scripts/benchmark): what
// each costs at 600x600 on one core, maps included (they are made for every frame).
//
//   Stages/<figure>   the chapter's figures, each with its stages on
#include "benchmark_main.h"
#include "scenes.h"

void RegisterAll() {
  RegisterFigures("Stages", Figures({}));
}
