// The main() every benchmark program shares: it registers the program's benchmarks,
// then hands the command line to Google Benchmark.
#pragma once

// Defined by each benchmark program: registers its benchmarks.
void RegisterAll();
