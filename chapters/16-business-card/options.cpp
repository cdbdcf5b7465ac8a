#include "options.h"

#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace {

constexpr int kMaxSamples = 4096;

}  // namespace

void AddChapterOptions(CLI::App& app, ChapterSettings& settings) {
  struct Given {
    int samples = kCardSamples;
    int seed = static_cast<int>(kDefaultSeed);
    std::vector<std::string> optimizations{"all"};
    int threads = 0;  // 0: one per core
  };
  auto given = std::make_shared<Given>();
  cgfs::SetDefaultSize(app, std::to_string(kCardSide) + "x" + std::to_string(kCardSide));
  cgfs::AddIntOption(app, "samples", given->samples,
                     "samples per pixel of the card (default 64, as on the card)", "N", 1,
                     kMaxSamples);
  cgfs::AddIntOption(app, "seed", given->seed, "the random numbers' seed (default 1)", "N", 0,
                     std::numeric_limits<int>::max());
  cgfs::AddListOption(app, "optimizations", given->optimizations,
                      "none, all (default), or a comma list of threads, bound", "LIST",
                      kOptimizationNames);
  cgfs::AddThreadsOption(app, given->threads);
  cgfs::AfterParsing(app, [given, &settings] {
    Optimizations chosen = OptimizationsNamed(given->optimizations);
    chosen.threads = cgfs::WorkersChosen(chosen.threads, given->threads);
    settings.card = {given->samples, static_cast<std::uint32_t>(given->seed), chosen};
  });
}
