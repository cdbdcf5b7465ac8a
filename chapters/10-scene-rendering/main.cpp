// Chapter 10, "Describing and Rendering a Scene": renders the chapter's figures into
// out/10-scene-rendering/.
#include "cgfs/chapter_main.h"
#include "rasterizer.h"

int main(int argc, char** argv) {
  cgfs::ChapterProgram program(
      "10-scene-rendering",
      "Chapter 10, Describing and Rendering a Scene: models, instances, transforms and a camera.");
  return program.Run(argc, argv, [] { return Figures(); });
}
