#include "options.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "program/arguments.h"
#include "program/error.h"
#include "program/model_file.h"

namespace {

// OBJ's right-handed coordinates in the book's left-handed ones.
Vec3 BookCoordinates(const glm::dvec3& v) {
  return {v.x, v.y, -v.z};
}

// Every edge used once in each direction: a surface without holes, consistently wound.
bool IsClosed(const Model& model) {
  std::vector<std::pair<int, int>> edges;  // (from, to) of every triangle, sorted
  edges.reserve(3 * model.triangles.size());
  for (const Triangle& triangle : model.triangles) {
    for (int k = 0; k < 3; ++k) {
      edges.emplace_back(triangle.v[k], triangle.v[(k + 1) % 3]);
    }
  }
  std::sort(edges.begin(), edges.end());
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const bool again = e + 1 < edges.size() && edges[e + 1] == edges[e];
    const std::pair<int, int> back(edges[e].second, edges[e].first);
    if (again || !std::binary_search(edges.begin(), edges.end(), back)) {
      return false;
    }
  }
  return true;
}

}  // namespace

void AddChapterOptions(CLI::App& app, ChapterSettings& settings) {
  auto file = std::make_shared<std::string>();
  cgfs::AddTextOption(app, "model", *file,
                      "a Wavefront OBJ model to draw instead of the chapter's figures (the "
                      "figure 'model', in front of the camera)",
                      "FILE.obj");
  cgfs::AfterParsing(app, [file, &settings] {
    if (file->empty()) {
      return;
    }
    const cgfs::ModelFile model = cgfs::ReadModelFile(*file);
    for (const std::string& warning : model.warnings) {
      cgfs::Warn(*file + ": " + warning);
    }
    settings.model = std::make_shared<const Model>(ModelFromFile(model));
    settings.model_name = std::filesystem::path(*file).filename().string();
  });
}

Model ModelFromFile(const cgfs::ModelFile& file) {
  Model model;
  for (const glm::dvec3& position : file.positions) {
    model.vertices.push_back(BookCoordinates(position));
  }
  for (const cgfs::ModelFile::Face& face : file.faces) {
    // Its corners the other way round (see options.h).
    const std::array<cgfs::ModelFile::Corner, 3> corners = {face.corners[0], face.corners[2],
                                                            face.corners[1]};
    const Color color = face.material >= 0
                            ? file.materials[static_cast<std::size_t>(face.material)].diffuse
                            : cgfs::ModelFile::Material{}.diffuse;
    Triangle triangle{{corners[0].position, corners[1].position, corners[2].position}, color};
    model.triangles.push_back(triangle);
  }
  model.closed = IsClosed(model);
  return model;
}
