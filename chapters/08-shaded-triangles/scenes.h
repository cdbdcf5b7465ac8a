// The figures of the chapter.
#pragma once

#include <vector>

#include "program/figure.h"
#include "shaded_triangles.h"

inline constexpr char kChapterDescription[] =
    "Chapter 8, Shaded Triangles: an intensity per vertex, interpolated across the triangle.";

// Every figure this chapter draws.
std::vector<cgfs::Figure> Figures();
