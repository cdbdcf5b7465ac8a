// Faster, with chapter 5's ideas, each a switch, so that each can be measured alone
// (--optimizations on the command line, see options.h). Neither changes the image.
#pragma once

#include <string>

struct Optimizations {
  // Chapter 5's "Parallelism": how many workers take tiles of the canvas; 1 is no
  // threads. Every pixel has its own random numbers, so the order does not matter.
  int threads = 1;
  // Chapter 5's "Hierarchical Structures", in a simple form: a box around each of the
  // letters, each tested before its spheres (bound.h).
  bool bound = false;
};

// Both, with one worker per core.
Optimizations AllOptimizations();

// Reads a --optimizations value: "none", "all", or a comma list of threads,bound.
// Throws cgfs::UsageError naming what it does not know.
Optimizations ParseOptimizations(const std::string& list);

// The optimisations the chapter's figures are drawn with: `all` unless the command
// line says otherwise.
Optimizations& ChosenOptimizations();
