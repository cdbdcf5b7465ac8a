// Chapter 11, "Clipping": renders the chapter's figures into out/11-clipping/.
#include "cgfs/chapter_main.h"
#include "rasterizer.h"

int main(int argc, char** argv) {
  cgfs::ChapterProgram program("11-clipping",
                               "Chapter 11, Clipping: whole objects by bounding sphere, then "
                               "triangles against five planes.");
  return program.Run(argc, argv, [] { return Figures(); });
}
