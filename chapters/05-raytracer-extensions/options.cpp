#include "options.h"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

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
  cgfs::AddThreadsOption(app, given->threads);
  cgfs::AddModelOption(app, given->model, "the figures 'model' and its cost view");
  cgfs::AfterParsing(app, [given, &settings] {
    settings.optimizations = OptimizationsNamed(given->names);
    settings.optimizations.threads =
        cgfs::WorkersChosen(settings.optimizations.threads, given->threads);
    if (!given->model.empty()) {
      settings.model = std::make_shared<const std::vector<Triangle>>(
          TrianglesFromFile(cgfs::ReadBookModel(given->model)));
      settings.model_name = std::filesystem::path(given->model).filename().string();
    }
  });
}

std::vector<Triangle> TrianglesFromFile(const cgfs::BookModel& file) {
  std::vector<Triangle> triangles;
  const std::vector<Vec3>& V = file.vertices;
  for (const cgfs::BookModel::Triangle& T : file.triangles) {
    triangles.push_back(Triangle{V[T.v[0]], V[T.v[1]], V[T.v[2]], T.color, 100});
  }
  return triangles;
}
