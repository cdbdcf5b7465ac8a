#include "options.h"

#include <memory>
#include <string>
#include <vector>

#include "program/arguments.h"
#include "program/error.h"
#include "program/model_file.h"

namespace {

constexpr int kMaxThreads = 256;

// OBJ's right-handed coordinates in the book's left-handed ones.
Vec3 BookCoordinates(const glm::dvec3& v) {
  return {v.x, v.y, -v.z};
}

// Reads --model's file into `settings`, saying what was left out of it.
void ReadModel(const std::string& file, ChapterSettings& settings) {
  const cgfs::ModelFile model = cgfs::ReadModelFile(file);
  for (const std::string& warning : model.warnings) {
    cgfs::Warn(file + ": " + warning);
  }
  settings.model = std::make_shared<const std::vector<Triangle>>(TrianglesFromFile(model));
  settings.model_name = std::filesystem::path(file).filename().string();
}

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
      ReadModel(given->model, settings);
    }
  });
}

std::vector<Triangle> TrianglesFromFile(const cgfs::ModelFile& file) {
  std::vector<Triangle> triangles;
  for (const cgfs::ModelFile::Face& face : file.faces) {
    const Color color = face.material >= 0
                            ? file.materials[static_cast<std::size_t>(face.material)].diffuse
                            : cgfs::ModelFile::Material{}.diffuse;
    const auto corner = [&](int k) {
      return BookCoordinates(file.positions[static_cast<std::size_t>(
          face.corners[static_cast<std::size_t>(k)].position)]);
    };
    // Its corners the other way round, so that N = (B - A) x (C - A) still points out.
    triangles.push_back(Triangle{corner(0), corner(2), corner(1), color, 100});
  }
  return triangles;
}
