// The scenes of the chapter's figures, and the figures themselves.
#pragma once

#include <vector>

#include "program/figure.h"
#include "raytracer.h"

inline constexpr char kChapterDescription[] =
    "Chapter 4, Shadows and Reflections: shadow rays, mirrors and recursive TraceRay.";

// Figure 4-4: the shiny scene of chapter 3, now casting shadows, on white.
Scene SceneShadows();
// Figures 4-6 to 4-8: the same spheres, each a little reflective, on black.
Scene SceneReflections();
// The same with the blue and green spheres where the book's chapter 4 listing puts
// them: blue at (-2, 1, 3), green at (2, 1, 3).
Scene SceneReflectionsBookLayout();

// Every figure this chapter draws.
std::vector<cgfs::Figure> Figures();
