#include "options.h"

#include <memory>
#include <string>
#include <vector>

#include "program/arguments.h"
#include "program/error.h"

namespace {

constexpr int kMaxThreads = 256;

}  // namespace

void AddChapterOptions(CLI::App& app, ChapterSettings& settings) {
  struct Given {
    std::vector<std::string> names{"all"};
    int threads = 0;  // 0: one per core
  };
  auto given = std::make_shared<Given>();
  cgfs::AddListOption(app, "optimizations", given->names,
                      "none, all (default: every exact one), or a comma list of threads, "
                      "cache, shadow-any-hit, shadow-coherence, bvh, subsampling",
                      "LIST", kOptimizationNames);
  cgfs::AddIntOption(app, "threads", given->threads,
                     "workers when 'threads' is on (default: one per core)", "N", 1, kMaxThreads);
  cgfs::AfterParsing(app, [given, &settings] {
    Optimizations chosen = OptimizationsNamed(given->names);
    if (given->threads > 1 && chosen.threads == 1) {
      throw cgfs::UsageError("--threads " + std::to_string(given->threads) +
                             " needs 'threads' in --optimizations");
    }
    if (given->threads > 0 && chosen.threads > 1) {
      chosen.threads = given->threads;
    }
    settings.optimizations = chosen;
  });
}
