// Chapter 4, "Shadows and Reflections": renders the chapter's figures into
// out/04-shadows-reflections/.
#include <string>

#include "cgfs/chapter_main.h"
#include "raytracer.h"

int main(int argc, char** argv) {
  cgfs::ChapterProgram program(
      "04-shadows-reflections",
      "Chapter 4, Shadows and Reflections: shadow rays, mirrors and recursive TraceRay.");
  int recursion_depth = kDefaultRecursionDepth;
  std::string layout = "demo";
  program.Options().AddInt("--recursion-depth", "N",
                           "bounces for fig-4-8-reflections, 0..10 (default 3)", &recursion_depth,
                           0, 10);
  program.Options().AddString("--scene", "demo|book",
                              "blue and green spheres as in the demos (default) or the book's "
                              "chapter 4 listing",
                              &layout);
  return program.Run(argc, argv, [&] {
    if (layout != "demo" && layout != "book") {
      throw cgfs::UsageError("--scene: '" + layout + "' is not demo or book");
    }
    return Figures(recursion_depth, layout == "book" ? SphereLayout::kBook : SphereLayout::kDemo);
  });
}
