// The models and scenes of the chapter's figures, and the figures themselves.
#pragma once

#include <vector>

#include "clipping.h"
#include "options.h"
#include "program/figure.h"
#include "scene_rendering.h"

inline constexpr char kChapterDescription[] =
    "Chapter 13, Shading: lighting triangles; flat, Gouraud and Phong shading; normals in "
    "the model.";

// The cube of "Representing a Cube": edge 2, centred on the origin, each face two
// triangles of one colour, wound so that (V1 - V0) x (V2 - V0) points outwards; every
// corner's normal is its face's normal.
const Model& CubeModel();

// The scene of Figure 10-10.
Scene SceneTransformedCubes();

// Figures 13-1 to 13-9: Figure 10-10's cubes, a green sphere, and three lights.
Scene SceneShading();
// Figures 13-7 and 13-10: one large face, lit by a point light close to it, and a
// small yellow sphere that marks where the light is.
Scene SceneCloseLight();
// Figure 13-11: the spheres and lights of the ray tracer's chapters 3 and 4, and a
// yellow floor in place of their large ground sphere.
Scene SceneRaytracerSpheres();

// A model of the reader's own (--model) seen from a camera at the origin: scaled and
// moved so that its bounding sphere has radius 1 and its centre 3 units ahead, lit by the lights of
// chapter 13's figures.
Scene SceneModel(const Model& model);

// Every figure this chapter draws, made with `settings`; with a model in them, only the
// figures of it.
std::vector<cgfs::Figure> Figures(const ChapterSettings& settings = {});
