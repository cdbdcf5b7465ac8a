#include "options.h"

#include <string>

#include "cgfs/arguments.h"
#include "cgfs/error.h"
#include "optimizations.h"

namespace {

constexpr int kMaxThreads = 256;

std::string optimizations_text = "all";
int threads_given = 0;  // 0: one per core

}  // namespace

void AddChapterOptions(CLI::App& app) {
  cgfs::AddTextOption(app, "optimizations", optimizations_text,
                      "none, all (default: every exact one), or a comma list of threads, "
                      "cache, shadow-any-hit, shadow-coherence, bvh, subsampling",
                      "LIST");
  cgfs::AddIntOption(app, "threads", threads_given,
                     "workers when 'threads' is on (default: one per core)", "N", 1, kMaxThreads);
  cgfs::AfterParsing(app, [] {
    Optimizations chosen = ParseOptimizations(optimizations_text);
    if (threads_given > 1 && chosen.threads == 1) {
      throw cgfs::UsageError("--threads " + std::to_string(threads_given) +
                             " needs 'threads' in --optimizations");
    }
    if (threads_given > 0 && chosen.threads > 1) {
      chosen.threads = threads_given;
    }
    ChosenOptimizations() = chosen;
  });
}
