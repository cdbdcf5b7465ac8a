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

int samples_given = kCardSamples;
int seed_given = static_cast<int>(kDefaultSeed);
std::string optimizations_text = "all";
int threads_given = 0;  // 0: one per core

}  // namespace

void AddChapterOptions(CLI::App& app) {
  cgfs::SetDefaultSize(app, std::to_string(kCardSide) + "x" + std::to_string(kCardSide));
  cgfs::AddIntOption(app, "samples", samples_given,
                     "samples per pixel of the card (default 64, as on the card)", "N", 1,
                     kMaxSamples);
  cgfs::AddIntOption(app, "seed", seed_given, "the random numbers' seed (default 1)", "N", 0,
                     std::numeric_limits<int>::max());
  cgfs::AddTextOption(app, "optimizations", optimizations_text,
                      "none, all (default), or a comma list of threads, bound", "LIST");
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
    ChosenSamples() = samples_given;
    ChosenSeed() = static_cast<std::uint32_t>(seed_given);
  });
}
