// Chapter 7, "Filled Triangles": renders the chapter's figures into out/07-filled-triangles/.
#include "cgfs/chapter_main.h"
#include "rasterizer.h"

int main(int argc, char** argv) {
  cgfs::ChapterProgram program(
      "07-filled-triangles",
      "Chapter 7, Filled Triangles: wireframe triangles, and filled ones as horizontal segments.");
  return program.Run(argc, argv, [] { return Figures(); });
}
