// The main() every benchmark program shares: it registers the program's benchmarks,
// then hands the command line to Google Benchmark.
#pragma once

#include <string>
#include <vector>

#include "program/figure.h"

// Defined by each benchmark program: registers its benchmarks.
void RegisterAll();

// One benchmark per figure, named "<group>/<figure>": the figure drawn at 600x600, as
// the chapter program and --window draw it, timed in milliseconds.
void RegisterFigures(const std::string& group, const std::vector<cgfs::Figure>& figures);
