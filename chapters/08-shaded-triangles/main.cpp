// Chapter 8, "Shaded Triangles": renders the chapter's figures into out/08-shaded-triangles/.
#include "cgfs/chapter_main.h"
#include "rasterizer.h"

int main(int argc, char** argv) {
  cgfs::ChapterProgram program(
      "08-shaded-triangles",
      "Chapter 8, Shaded Triangles: an intensity per vertex, interpolated across the triangle.");
  return program.Run(argc, argv, [] { return Figures(); });
}
