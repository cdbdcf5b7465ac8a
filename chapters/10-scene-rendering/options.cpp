#include "options.h"

#include <filesystem>
#include <memory>
#include <string>

void AddChapterOptions(CLI::App& app, ChapterSettings& settings) {
  auto file = std::make_shared<std::string>();
  cgfs::AddModelOption(app, *file, "the figure 'model'");
  cgfs::AfterParsing(app, [file, &settings] {
    if (!file->empty()) {
      settings.model = std::make_shared<const Model>(ModelFromFile(cgfs::ReadBookModel(*file)));
      settings.model_name = std::filesystem::path(*file).filename().string();
    }
  });
}

Model ModelFromFile(const cgfs::BookModel& file) {
  Model model{file.vertices, {}};
  for (const cgfs::BookModel::Triangle& T : file.triangles) {
    model.triangles.push_back({T.v, T.color});
  }
  return model;
}
