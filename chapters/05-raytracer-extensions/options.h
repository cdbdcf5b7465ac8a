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
struct ModelFile;
}

// What the chapter's figures are made with.
struct ChapterSettings {
  Optimizations optimizations = AllOptimizations();
  // The reader's model (--model) as triangles, or none: the chapter's own figures.
  std::shared_ptr<const std::vector<Triangle>> model;
  std::string model_name;  // its file's name, for the figures' captions
};

// Declares --optimizations, --threads and --model on `app`; once the command line is
// read, the optimisations they name and the model (read by cgfs::ReadModelFile,
// program/model_file.h) are in `settings`, and what was left out of the model has been
// said in one warning line each.
void AddChapterOptions(CLI::App& app, ChapterSettings& settings);

// A model file's triangles as the chapter's Triangle objects, each in its material's
// colour (Kd), a little shiny. OBJ's coordinates are right-handed and the book's
// left-handed (the camera looks along +z, x to its right, y up): z is negated, which
// turns the model's front (+z in OBJ) towards the camera, and each triangle's corners
// are listed the other way round, so that its N = (B - A) x (C - A) still points out.
std::vector<Triangle> TrianglesFromFile(const cgfs::ModelFile& file);
