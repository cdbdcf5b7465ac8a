// The chapter's program: draws the chapter's figures into out/<chapter>/ (see the
// chapter's README.md, or run it with --help). This file is the same in every
// chapter: the figures and the one-line description come from scenes.h, and a
// chapter with command-line options of its own declares them in options.h, with the
// settings they fill in, which its figures are then made with.
#include "program/chapter_program.h"
#include "scenes.h"
#if __has_include("options.h")
#include "options.h"
#endif

int main(int argc, char** argv) {
  cgfs::ChapterProgram program(CGFS_CHAPTER, kChapterDescription);
#if __has_include("options.h")
  ChapterSettings settings;
  AddChapterOptions(program.Options(), settings);
  return program.Run(argc, argv, [&settings] { return Figures(settings); });
#else
  return program.Run(argc, argv, Figures);
#endif
}
