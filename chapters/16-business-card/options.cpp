#include "options.h"

#include <limits>
#include <string>

#include "cgfs/arguments.h"
#include "cgfs/error.h"
#include "optimizations.h"
#include "scenes.h"

namespace {

constexpr int kMaxSamples = 4096;
constexpr int kMaxThreads = 256;

int samples = kCardSamples;
int seed = static_cast<int>(kDefaultSeed);
std::string optimizations_text = "all";
int threads = 0;  // 0: one per core

}  // namespace

void AddChapterOptions(CLI::App& app) {
  cgfs::SetDefaultSize(app, std::to_string(kCardSide) + "x" + std::to_string(kCardSide));
  cgfs::AddIntOption(app, "samples", samples,
                     "samples per pixel of the card (default 64, as on the card)", "N", 1,
                     kMaxSamples);
  cgfs::AddIntOption(app, "seed", seed, "the random numbers' seed (default 1)", "N", 0,
                     std::numeric_limits<int>::max());
  cgfs::AddTextOption(app, "optimizations", optimizations_text,
                      "none, all (default), or a comma list of threads, bound", "LIST");
  cgfs::AddIntOption(app, "threads", threads,
                     "workers when 'threads' is on (default: one per core)", "N", 1, kMaxThreads);
  cgfs::AfterParsing(app, [] {
    Optimizations chosen = ParseOptimizations(optimizations_text);
    if (threads > 1 && chosen.threads == 1) {
      throw cgfs::UsageError("--threads " + std::to_string(threads) +
                             " needs 'threads' in --optimizations");
    }
    if (threads > 0 && chosen.threads > 1) {
      chosen.threads = threads;
    }
    ChosenOptimizations() = chosen;
    ChosenSamples() = samples;
    ChosenSeed() = static_cast<std::uint32_t>(seed);
  });
}
