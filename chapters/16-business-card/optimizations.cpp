#include "optimizations.h"

#include <algorithm>
#include <thread>

Optimizations AllOptimizations() {
  Optimizations all;
  all.threads = static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
  all.bound = true;
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
    } else if (name == "bound") {
      chosen.bound = true;
    }
  }
  return chosen;
}
