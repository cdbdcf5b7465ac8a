// The chapter's own command-line option, --model FILE (a model of the reader's own,
// drawn instead of the chapter's figures: scenes.h), and the settings it fills in.
#pragma once

#include <memory>
#include <string>

#include "program/arguments.h"
#include "program/book_model.h"
#include "scene.h"

// What the chapter's figures are made with.
struct ChapterSettings {
  std::shared_ptr<const Model> model;  // the reader's (--model), or none: the figures
  std::string model_name;              // its file's name, for the figure's caption
};

// Declares --model on `app`; once the command line is read, the model (ReadBookModel,
// which says what it left out) is in `settings`.
void AddChapterOptions(CLI::App& app, ChapterSettings& settings);

// A model file in the book's coordinates as the chapter's Model: each triangle in its material's
// colour (Kd), closed if the file's surface is ("Back Face Culling").
Model ModelFromFile(const cgfs::BookModel& file);
