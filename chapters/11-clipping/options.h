// The chapter's own command-line option, --model FILE, and the settings it fills in: a
// Wavefront OBJ model of the reader's own, drawn instead of the chapter's figures (see
// scenes.h).
#pragma once

#include <memory>
#include <string>

#include "scene.h"

namespace CLI {
class App;
}
namespace cgfs {
struct BookModel;
}

// What the chapter's figures are made with.
struct ChapterSettings {
  // The reader's model (--model), or none: the chapter's own figures.
  std::shared_ptr<const Model> model;
  std::string model_name;  // its file's name, for the figure's caption
};

// Declares --model on `app`; once the command line is read, the model (read by
// cgfs::ReadBookModel, program/book_model.h) is in `settings`, and what was left out of
// it has been said in one warning line each.
void AddChapterOptions(CLI::App& app, ChapterSettings& settings);

// A model file, in the book's coordinates (cgfs::InBookCoordinates), as the chapter's
// Model: each triangle in its material's colour (Kd).
Model ModelFromFile(const cgfs::BookModel& file);
