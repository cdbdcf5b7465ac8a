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
struct ModelFile;
}

// What the chapter's figures are made with.
struct ChapterSettings {
  // The reader's model (--model), or none: the chapter's own figures.
  std::shared_ptr<const Model> model;
  std::string model_name;  // its file's name, for the figure's caption
};

// Declares --model on `app`; once the command line is read, the model (read by
// cgfs::ReadModelFile, program/model_file.h) is in `settings`, and what was left out of
// it has been said in one warning line each.
void AddChapterOptions(CLI::App& app, ChapterSettings& settings);

// A model file's triangles as the chapter's Model. OBJ's coordinates are right-handed
// and the book's left-handed (the camera looks along +z, x to its right, y up): z is
// negated, which turns the model's front (+z in OBJ) towards the camera, and each
// triangle's corners are listed the other way round, so that (V1 - V0) x (V2 - V0)
// still points outwards. Each triangle has its material's colour (Kd).
Model ModelFromFile(const cgfs::ModelFile& file);
