// The scenes of the chapter's figures, and the figures themselves.
#pragma once

#include <vector>

#include "program/figure.h"
#include "raytracer.h"

inline constexpr char kChapterDescription[] =
    "Chapter 3, Light: ambient, point and directional lights, diffuse and specular reflection.";

// Figure 3-7: the chapter 2 spheres and the yellow floor, all matte.
Scene SceneDiffuse();
// Figure 3-16: the same spheres, shiny.
Scene SceneSpecular();

// Every figure this chapter draws.
std::vector<cgfs::Figure> Figures();
