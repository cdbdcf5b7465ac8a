#include "optimizations.h"

#include <algorithm>
#include <sstream>
#include <thread>

#include "cgfs/error.h"

Optimizations AllOptimizations() {
  Optimizations all;
  all.threads = static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
  all.bound = true;
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
    } else if (name == "bound") {
      chosen.bound = true;
    } else {
      throw cgfs::UsageError("--optimizations: unknown '" + name +
                             "'; use none, all, or a comma list of threads, bound");
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
