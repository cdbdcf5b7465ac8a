#include "options.h"

#include <CLI/CLI.hpp>

#include <string>

#include "cgfs/error.h"
#include "optimizations.h"

namespace {

constexpr int kMaxThreads = 256;

std::string optimizations_text = "all";
int threads = 0;  // 0: one per core

}  // namespace

void AddChapterOptions(CLI::App& app) {
  app.add_option("--optimizations", optimizations_text,
                 "none, all (default: every exact one), or a comma list of threads, cache, "
                 "shadow-any-hit, shadow-coherence, bvh, subsampling")
      ->type_name("LIST");
  app.add_option("--threads", threads, "workers when 'threads' is on (default: one per core)")
      ->type_name("N")
      ->check(CLI::Range(1, kMaxThreads));
  app.final_callback([] {
    Optimizations chosen = ParseOptimizations(optimizations_text);
    if (threads > 1 && chosen.threads == 1) {
      throw cgfs::UsageError("--threads " + std::to_string(threads) +
                             " needs 'threads' in --optimizations");
    }
    if (threads > 0 && chosen.threads > 1) {
      chosen.threads = threads;
    }
    ChosenOptimizations() = chosen;
  });
}
