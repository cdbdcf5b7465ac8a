// The chapter's ways of going faster ("Optimizations"), each a switch, so that each
// can be measured alone (--optimizations on the command line, see options.h).
#pragma once

#include <string>

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

// Reads a --optimizations value: "none", "all", or a comma list of
// threads,cache,shadow-any-hit,shadow-coherence,bvh,subsampling. Throws
// cgfs::UsageError naming what it does not know.
Optimizations ParseOptimizations(const std::string& list);

// The optimisations the chapter's figures are drawn with: `all` unless the command
// line says otherwise.
Optimizations& ChosenOptimizations();
