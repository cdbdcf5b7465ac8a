// The models and scenes of the chapter's figures, and the figures themselves.
#pragma once

#include <vector>

#include "clipping.h"
#include "options.h"
#include "program/figure.h"
#include "scene_rendering.h"

inline constexpr char kChapterDescription[] =
    "Chapter 11, Clipping: the clipping volume, bounding spheres, splitting triangles.";

// The cube of "Representing a Cube": edge 2, centred on the origin, each face two
// triangles of one colour, wound so that (V1 - V0) x (V2 - V0) points outwards.
const Model& CubeModel();

// The scene of Figure 10-10.
Scene SceneTransformedCubes();

// The scene of Figure 10-10 with a third cube, behind the camera.
Scene SceneWithCubeBehindCamera();
// A cube so close to the camera that the near plane cuts it.
Scene SceneCubeCutByNearPlane();

// A model of the reader's own (--model) seen from a camera at the origin: scaled and
// moved so that its bounding sphere has radius 1 and its centre 3 units ahead.
Scene SceneModel(const Model& model);

// Every figure this chapter draws, made with `settings`; with a model in them, only the
// figures of it.
std::vector<cgfs::Figure> Figures(const ChapterSettings& settings = {});
