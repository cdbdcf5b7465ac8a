// The chapter's own command-line options, which optimisations to use and how many
// threads (see optimizations.h), and a Wavefront OBJ model of the reader's own to
// draw instead of the chapter's figures; and the settings they fill in.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "objects.h"
#include "optimizations.h"

namespace CLI {
class App;
}
namespace cgfs {
struct BookModel;
}

// What the chapter's figures are made with.
struct ChapterSettings {
  Optimizations optimizations = AllOptimizations();
  // The reader's model (--model) as triangles, or none: the chapter's own figures.
  std::shared_ptr<const std::vector<Triangle>> model;
  std::string model_name;  // its file's name, for the figures' captions
};

// Declares --optimizations, --threads and --model on `app`; once the command line is
// read, the optimisations they name and the model (read by cgfs::ReadBookModel,
// program/book_model.h) are in `settings`, and what was left out of the model has been
// said in one warning line each.
void AddChapterOptions(CLI::App& app, ChapterSettings& settings);

// A model file, in the book's coordinates (cgfs::InBookCoordinates), as the chapter's
// Triangle objects, each in its material's colour (Kd), a little shiny.
std::vector<Triangle> TrianglesFromFile(const cgfs::BookModel& file);
