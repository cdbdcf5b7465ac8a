#include "options.h"

#include <filesystem>
#include <memory>
#include <string>

#include "program/arguments.h"
#include "program/book_model.h"

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
    settings.model = std::make_shared<const Model>(ModelFromFile(cgfs::ReadBookModel(*file)));
    settings.model_name = std::filesystem::path(*file).filename().string();
  });
}

Model ModelFromFile(const cgfs::BookModel& file) {
  Model model{file.vertices, {}, file.closed};
  for (const cgfs::BookModel::Triangle& T : file.triangles) {
    model.triangles.push_back({T.v, T.color});
  }
  return model;
}
