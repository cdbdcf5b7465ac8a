#include "options.h"

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "program/arguments.h"
#include "program/book_model.h"
#include "program/error.h"

namespace {

constexpr int kMaxThreads = 256;

}  // namespace

void AddChapterOptions(CLI::App& app, ChapterSettings& settings) {
  struct Given {
    std::vector<std::string> names{"all"};
    int threads = 0;  // 0: one per core
    std::string model;
  };
  auto given = std::make_shared<Given>();
  cgfs::AddListOption(app, "optimizations", given->names,
                      "none, all (default: every exact one), or a comma list of threads, "
                      "cache, shadow-any-hit, shadow-coherence, bvh, subsampling",
                      "LIST", kOptimizationNames);
  cgfs::AddIntOption(app, "threads", given->threads,
                     "workers when 'threads' is on (default: one per core)", "N", 1, kMaxThreads);
  cgfs::AddTextOption(app, "model", given->model,
                      "a Wavefront OBJ model to draw instead of the chapter's figures (the "
                      "figures 'model' and its cost view, in front of the camera)",
                      "FILE.obj");
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
    if (!given->model.empty()) {
      settings.model = std::make_shared<const std::vector<Triangle>>(
          TrianglesFromFile(cgfs::ReadBookModel(given->model)));
      settings.model_name = std::filesystem::path(given->model).filename().string();
    }
  });
}

std::vector<Triangle> TrianglesFromFile(const cgfs::BookModel& file) {
  std::vector<Triangle> triangles;
  for (const cgfs::BookModel::Triangle& T : file.triangles) {
    const auto corner = [&](std::size_t k) {
      return file.vertices[static_cast<std::size_t>(T.v[k])];
    };
    triangles.push_back(Triangle{corner(0), corner(1), corner(2), T.color, 100});
  }
  return triangles;
}
