// The models and scenes of the chapter's figures, and the figures themselves.
#pragma once

#include <vector>

#include "clipping.h"
#include "options.h"
#include "program/figure.h"
#include "scene_rendering.h"

inline constexpr char kChapterDescription[] =
    "Chapter 12, Hidden Surface Removal: solid triangles, the painter's algorithm, the depth "
    "buffer, back-face culling.";

// The cube of "Representing a Cube": edge 2, centred on the origin, each face two
// triangles of one colour, wound so that (V1 - V0) x (V2 - V0) points outwards.
const Model& CubeModel();

// The cube without its blue face (z = -1): an open box, whose inside can be seen.
const Model& OpenBoxModel();

// The scene of Figure 10-10.
Scene SceneTransformedCubes();

// Four squares one behind the other, listed nearest first.
Scene SceneOverlappingSquares();
// Figure 12-2: three long triangles, each lying over the next one and under the
// previous one. No order of the three draws them correctly.
Scene SceneCyclicOverlap();
// Two triangles that pass through each other: each is in front on one side of the
// line where they cross.
Scene SceneIntersectingTriangles();
// A long floor and a ramp rising out of it at a shallow angle, both stretching far
// away: where they cross shows whether depths are interpolated correctly.
Scene SceneCrossingPlanes();
// The open box, its opening towards the camera, seen from above.
Scene SceneOpenBox();
// The same box with its model said to be closed, which it is not: culling removes its
// inside faces.
Scene SceneOpenBoxSaidClosed();

// A model of the reader's own (--model) seen from a camera at the origin: scaled and
// moved so that its bounding sphere has radius 1 and its centre 3 units ahead.
Scene SceneModel(const Model& model);

// Every figure this chapter draws, made with `settings`; with a model in them, only the
// figures of it.
std::vector<cgfs::Figure> Figures(const ChapterSettings& settings = {});
