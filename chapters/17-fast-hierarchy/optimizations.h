// The chapter's ways of going faster ("Optimizations"), each a switch, so that each
// can be measured alone (--optimizations on the command line, see options.h).
#pragma once

#include <string>
#include <vector>

struct Optimizations {
  // "Parallelism": how many workers take tiles of the canvas; 1 is no threads.
  int threads = 1;
  // "Caching Invariants": r² per sphere, <CO,CO> for camera rays, <D,D> per ray.
  bool cache = false;
  // "Shadow Optimizations": a shadow ray stops at the first thing it hits ...
  bool shadow_any_hit = false;
  // ... and tries first the object that blocked the same light last time.
  bool shadow_coherence = false;
  // "Hierarchical Structures": a bounding-volume hierarchy over the objects.
  bool bvh = false;
  // "Subsampling": trace every other pixel, fill in the rest. The only one that
  // changes the image, so `all` leaves it out.
  bool subsampling = false;
};

// Every exact optimisation, with one worker per core.
Optimizations AllOptimizations();

// The names --optimizations takes: none, all, and each switch.
inline const std::vector<std::string> kOptimizationNames = {
    "none", "all", "threads", "cache", "shadow-any-hit", "shadow-coherence", "bvh", "subsampling"};

// The optimisations a list of those names turns on, together ("none" turns on
// nothing, "all" every exact one); `threads` with one worker per core.
Optimizations OptimizationsNamed(const std::vector<std::string>& names);
