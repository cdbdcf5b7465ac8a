#include "rasterizer.h"

// Figure 9-4 uses the author's demo cube: one unit wide, 5 to 6 units ahead and to
// the left. The book's listing has a cube from (-1,-1,1) to (1,1,2), whose front
// face projects to x, y = +-600 pixels: outside a 600x600 canvas.
Cube ChapterCube(CubeVariant variant) {
  if (variant == CubeVariant::kBook) {
    return {{-1, 1, 1}, {1, 1, 1}, {1, -1, 1}, {-1, -1, 1},
            {-1, 1, 2}, {1, 1, 2}, {1, -1, 2}, {-1, -1, 2}};
  }
  return {{-2, -0.5, 5}, {-2, 0.5, 5}, {-1, 0.5, 5}, {-1, -0.5, 5},
          {-2, -0.5, 6}, {-2, 0.5, 6}, {-1, 0.5, 6}, {-1, -0.5, 6}};
}

std::vector<cgfs::Figure> Figures(CubeVariant variant) {
  return {
      {"fig-9-4", "a wireframe cube in perspective (Figure 9-4)",
       [variant](Canvas& canvas) { DrawCube(ChapterCube(variant), canvas, Viewport{}); }},
  };
}
