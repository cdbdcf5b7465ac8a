#include "optimizations.h"

#include <algorithm>
#include <sstream>
#include <thread>

#include "cgfs/error.h"

Optimizations AllOptimizations() {
  Optimizations all;
  all.threads = static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
  all.cache = true;
  all.shadow_any_hit = true;
  all.shadow_coherence = true;
  all.bvh = true;
  return all;
}

Optimizations ParseOptimizations(const std::string& list) {
  if (list == "none") {
    return {};
  }
  if (list == "all") {
    return AllOptimizations();
  }
  Optimizations chosen;
  std::istringstream names(list);
  std::string name;
  bool any = false;
  while (std::getline(names, name, ',')) {
    any = true;
    if (name == "threads") {
      chosen.threads = AllOptimizations().threads;
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
    } else {
      throw cgfs::UsageError("--optimizations: unknown '" + name +
                             "'; use none, all, or a comma list of threads, cache, "
                             "shadow-any-hit, shadow-coherence, bvh, subsampling");
    }
  }
  if (!any || list.back() == ',') {
    throw cgfs::UsageError("--optimizations: '" + list + "' is not a list of optimisations");
  }
  return chosen;
}

Optimizations& ChosenOptimizations() {
  static Optimizations chosen = AllOptimizations();
  return chosen;
}
