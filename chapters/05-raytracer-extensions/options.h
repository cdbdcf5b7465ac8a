// The chapter's own command-line options, which optimisations to use and how many
// threads (see optimizations.h), and a Wavefront OBJ model of the reader's own to draw
// instead of the chapter's figures; and the settings they fill in.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "objects.h"
#include "optimizations.h"
#include "program/arguments.h"
#include "program/book_model.h"

// What the chapter's figures are made with.
struct ChapterSettings {
  Optimizations optimizations = AllOptimizations();
  std::shared_ptr<const std::vector<Triangle>> model;  // the reader's (--model), or none
  std::string model_name;                              // its file's name, for the figures' captions
};

// Declares --optimizations, --threads and --model on `app`; once the command line is
// read, what they give is in `settings` (the model read by ReadBookModel).
void AddChapterOptions(CLI::App& app, ChapterSettings& settings);

// A model file in the book's coordinates as the chapter's Triangle objects, each in its
// material's colour (Kd), a little shiny.
std::vector<Triangle> TrianglesFromFile(const cgfs::BookModel& file);
