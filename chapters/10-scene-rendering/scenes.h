// The models and scenes of the chapter's figures, and the figures themselves.
#pragma once

#include <vector>

#include "options.h"
#include "program/figure.h"
#include "scene_rendering.h"

inline constexpr char kChapterDescription[] =
    "Chapter 10, Describing and Rendering a Scene: models, instances, transforms and a camera.";

// The cube of "Representing a Cube": edge 2, centred on the origin, each face two
// triangles of one colour, wound so that (V1 - V0) x (V2 - V0) points outwards.
const Model& CubeModel();

// The scenes of Figures 10-3 and 10-10.
Scene SceneTwoCubes();
Scene SceneTransformedCubes();

// A model of the reader's own (--model) seen from a camera at the origin: scaled and
// moved so that its bounding sphere has radius 1 and its centre 3 units ahead.
Scene SceneModel(const Model& model);

// Every figure this chapter draws; with a model in `settings`, only the figure of it.
std::vector<cgfs::Figure> Figures(const ChapterSettings& settings = {});
