#include "optimizations.h"

#include <algorithm>
#include <thread>

Optimizations AllOptimizations() {
  Optimizations all;
  all.threads = static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
  all.cache = true;
  all.shadow_any_hit = true;
  all.shadow_coherence = true;
  all.bvh = true;
  return all;
}

Optimizations OptimizationsNamed(const std::vector<std::string>& names) {
  const Optimizations all = AllOptimizations();
  Optimizations chosen;
  for (const std::string& name : names) {
    if (name == "all") {
      chosen = all;
    } else if (name == "threads") {
      chosen.threads = all.threads;
    } else if (name == "cache") {
      chosen.cache = true;
    } else if (name == "shadow-any-hit") {
      chosen.shadow_any_hit = true;
    } else if (name == "shadow-coherence") {
      chosen.shadow_coherence = true;
    } else if (name == "bvh") {
      chosen.bvh = true;
    } else if (name == "subsampling") {
      chosen.subsampling = true;
    }
  }
  return chosen;
}
