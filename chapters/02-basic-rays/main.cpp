// Chapter 2, "Basic Ray Tracing": renders the chapter's figures into out/02-basic-rays/.
#include "cgfs/chapter_main.h"
#include "raytracer.h"

int main(int argc, char** argv) {
  cgfs::ChapterProgram program(
      "02-basic-rays",
      "Chapter 2, Basic Ray Tracing: one ray per pixel, the closest sphere's flat colour.");
  return program.Run(argc, argv, [] { return Figures(); });
}
