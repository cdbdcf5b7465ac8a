// The figures of the chapter.
#pragma once

#include <vector>

#include "program/figure.h"
#include "projection.h"

inline constexpr char kChapterDescription[] =
    "Chapter 9, Perspective Projection: 3-D points onto the canvas, and a wireframe cube.";

// The eight corners of a box, named as in Listing 9-1: A, B, C, D around the front
// face and the same letters on the back face.
struct Cube {
  Vec3 vAf{}, vBf{}, vCf{}, vDf{};
  Vec3 vAb{}, vBb{}, vCb{}, vDb{};
};

// The cube of Figure 9-4 (the author's demo): one unit wide, 5 to 6 units ahead.
Cube DemoCube();
// The cube Listing 9-1 prints, from (-1, -1, 1) to (1, 1, 2).
Cube BookListingCube();

// Listing 9-1: the twelve edges of the cube, each projected and drawn with
// DrawLine: the front face blue, the back face red, the edges between them green.
void DrawCube(const Cube& cube, Canvas& canvas, const Viewport& viewport);

// Every figure this chapter draws.
std::vector<cgfs::Figure> Figures();
