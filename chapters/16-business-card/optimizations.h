// Faster, with chapter 5's ideas, each a switch, so that each can be measured alone
// (--optimizations on the command line, see options.h). Neither changes the image.
#pragma once

#include <string>
#include <vector>

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

// The names --optimizations takes: none, all, and each switch.
inline const std::vector<std::string> kOptimizationNames = {"none", "all", "threads", "bound"};

// The optimisations a list of those names turns on, together ("none" turns on
// nothing, "all" both); `threads` with one worker per core.
Optimizations OptimizationsNamed(const std::vector<std::string>& names);
