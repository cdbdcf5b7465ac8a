// The scenes of the chapter's figures, and the figures themselves.
#pragma once

#include <vector>

#include "program/figure.h"
#include "raytracer.h"

inline constexpr char kChapterDescription[] =
    "Chapter 2, Basic Ray Tracing: one ray per pixel, the closest sphere's flat colour.";

// "Rendering our First Spheres": red, blue and green spheres on white.
Scene SceneThreeSpheres();
// The same with the huge yellow sphere that chapter 3 uses as a floor.
Scene SceneWithGround();

// Every figure this chapter draws.
std::vector<cgfs::Figure> Figures();
