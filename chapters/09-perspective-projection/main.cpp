// Chapter 9, "Perspective Projection": renders the chapter's figures into
// out/09-perspective-projection/.
#include <string>

#include "cgfs/chapter_main.h"
#include "rasterizer.h"

int main(int argc, char** argv) {
  cgfs::ChapterProgram program(
      "09-perspective-projection",
      "Chapter 9, Perspective Projection: 3-D points onto the canvas, and a wireframe cube.");
  std::string cube = "demo";
  program.Options().AddString("--cube", "demo|book",
                              "the demo's cube (default) or the book listing's, which mostly "
                              "falls off the canvas",
                              &cube);
  return program.Run(argc, argv, [&] {
    if (cube != "demo" && cube != "book") {
      throw cgfs::UsageError("--cube: '" + cube + "' is not demo or book");
    }
    return Figures(cube == "book" ? CubeVariant::kBook : CubeVariant::kDemo);
  });
}
