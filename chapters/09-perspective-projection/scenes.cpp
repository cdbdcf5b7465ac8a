#include "scenes.h"

// Figure 9-4 uses the author's demo cube: one unit wide, 5 to 6 units ahead and to
// the left.
Cube DemoCube() {
  return {{-2, -0.5, 5}, {-2, 0.5, 5}, {-1, 0.5, 5}, {-1, -0.5, 5},
          {-2, -0.5, 6}, {-2, 0.5, 6}, {-1, 0.5, 6}, {-1, -0.5, 6}};
}

// The book's listing has a cube whose front face lies on the projection plane z = 1
// and projects to x, y = +-600 pixels: outside a 600x600 canvas. Only its back face
// (+-300 pixels, the canvas border) and the ends of the edges between reach it.
Cube BookListingCube() {
  return {{-1, 1, 1}, {1, 1, 1}, {1, -1, 1}, {-1, -1, 1},
          {-1, 1, 2}, {1, 1, 2}, {1, -1, 2}, {-1, -1, 2}};
}

// Listing 9-1. Projection keeps straight lines straight, so an edge of the cube is
// the segment between its projected ends.
void DrawCube(const Cube& cube, Canvas& canvas, const Viewport& viewport) {
  // The front face
  DrawLine(ProjectVertex(cube.vAf, canvas, viewport), ProjectVertex(cube.vBf, canvas, viewport),
           cgfs::kBlue, canvas);
  DrawLine(ProjectVertex(cube.vBf, canvas, viewport), ProjectVertex(cube.vCf, canvas, viewport),
           cgfs::kBlue, canvas);
  DrawLine(ProjectVertex(cube.vCf, canvas, viewport), ProjectVertex(cube.vDf, canvas, viewport),
           cgfs::kBlue, canvas);
  DrawLine(ProjectVertex(cube.vDf, canvas, viewport), ProjectVertex(cube.vAf, canvas, viewport),
           cgfs::kBlue, canvas);

  // The back face
  DrawLine(ProjectVertex(cube.vAb, canvas, viewport), ProjectVertex(cube.vBb, canvas, viewport),
           cgfs::kRed, canvas);
  DrawLine(ProjectVertex(cube.vBb, canvas, viewport), ProjectVertex(cube.vCb, canvas, viewport),
           cgfs::kRed, canvas);
  DrawLine(ProjectVertex(cube.vCb, canvas, viewport), ProjectVertex(cube.vDb, canvas, viewport),
           cgfs::kRed, canvas);
  DrawLine(ProjectVertex(cube.vDb, canvas, viewport), ProjectVertex(cube.vAb, canvas, viewport),
           cgfs::kRed, canvas);

  // The front-to-back edges
  DrawLine(ProjectVertex(cube.vAf, canvas, viewport), ProjectVertex(cube.vAb, canvas, viewport),
           cgfs::kGreen, canvas);
  DrawLine(ProjectVertex(cube.vBf, canvas, viewport), ProjectVertex(cube.vBb, canvas, viewport),
           cgfs::kGreen, canvas);
  DrawLine(ProjectVertex(cube.vCf, canvas, viewport), ProjectVertex(cube.vCb, canvas, viewport),
           cgfs::kGreen, canvas);
  DrawLine(ProjectVertex(cube.vDf, canvas, viewport), ProjectVertex(cube.vDb, canvas, viewport),
           cgfs::kGreen, canvas);
}

std::vector<cgfs::Figure> Figures() {
  return {
      {"fig-9-4", "a wireframe cube in perspective (Figure 9-4)",
       [](Canvas& canvas) { DrawCube(DemoCube(), canvas, Viewport{}); }},
      {"book-listing-cube",
       "the cube Listing 9-1 prints: its front face projects outside the canvas",
       [](Canvas& canvas) { DrawCube(BookListingCube(), canvas, Viewport{}); }},
  };
}
